#ifndef MPM_GEOMETRY_HPP
#define MPM_GEOMETRY_HPP

#include <case/mpm_case_config.hpp>

#include <vector>

namespace mpm
{
namespace geometry
{
//---------------------------------------------------------------------------//
// Plane geometry on host for case set-up: body polygons and boundary
// polylines. Polygons are given without repeating the first vertex; a
// repeated closing vertex (last == first) is accepted and ignored. Either
// vertex orientation is accepted. Edge k joins vertex k to vertex k + 1
// (mod n) of the polygon without its closing vertex.
//---------------------------------------------------------------------------//

/*!
  \brief Whether point p lies inside the polygon (even-odd rule).

  Points exactly on an edge may be classified either way; a polygon with
  fewer than 3 distinct vertices contains no point.
*/
bool pointInPolygon( const std::vector<Point2>& polygon, const Point2& p );

//---------------------------------------------------------------------------//
/*!
  \brief Where the polygon's edges cross the line at height y, in
  increasing x: pointInPolygon( polygon, {x, y} ) is true exactly if an
  odd number of them are > x (the same test, edge by edge, with the same
  numbers). Empty for a polygon that pointInPolygon finds empty.

  \param crossings Filled (its storage is reused).
*/
void rowCrossings( const std::vector<Point2>& polygon, double y,
                   std::vector<double>& crossings );

//---------------------------------------------------------------------------//
/*!
  \brief Absolute area of a simple polygon (shoelace formula), m^2 for
  vertices in m.
*/
double polygonArea( const std::vector<Point2>& polygon );

//---------------------------------------------------------------------------//
/*!
  \brief Find two edges of the polygon that intersect or touch.

  Non-adjacent edges count if they share any point. Adjacent edges (which
  share a vertex) count if they overlap collinearly (the polygon folds back
  on itself) or if one of them has zero length.

  \param edge_a, edge_b On success, the indices of the two edges,
  edge_a < edge_b.
  \return true if the polygon is not simple.
*/
bool findSelfIntersection( const std::vector<Point2>& polygon, int& edge_a,
                           int& edge_b );

//---------------------------------------------------------------------------//
/*!
  \brief y(x) of a polyline by linear interpolation, m.

  The vertices must have strictly increasing x. Beyond its ends the
  polyline is extended horizontally (constant extrapolation).

  \throw std::invalid_argument if the polyline has no vertex.
*/
double polylineY( const std::vector<Point2>& polyline, double x );

//---------------------------------------------------------------------------//
/*!
  \brief Whether the closed segment ab meets the open axis-aligned square
  of half-width r centred on c: whether some point of the segment lies
  less than r from c in both x and y (its max-norm distance to c is < r).

  Exact for vertical, horizontal and degenerate (a == b) segments.
*/
bool segmentMeetsOpenSquare( const Point2& a, const Point2& b, const Point2& c,
                             double r );

} // namespace geometry
} // namespace mpm

#endif // MPM_GEOMETRY_HPP
