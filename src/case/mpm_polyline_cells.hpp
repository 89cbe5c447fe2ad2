#ifndef MPM_POLYLINE_CELLS_HPP
#define MPM_POLYLINE_CELLS_HPP

#include <case/mpm_case_config.hpp>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
// The grid cells a polyline passes through and the length of line in each:
// the geometry of a water inflow on a polyline (where = "polyline").
//---------------------------------------------------------------------------//

//! Length of a polyline: along the line, or its horizontal projection
//! (the sum of |dx| over its segments), m.
double polylineLength( const std::vector<Point2>& line, LineMeasure measure );

//! A piece of a polyline inside one cell, or on the edge between two.
struct PolylinePiece
{
    //! Flat index i * ny + j of the cell holding the piece, and of the
    //! cell on the other side when the piece runs along a grid line
    //! (-1: none, e.g. outside the grid).
    std::array<int, 2> cells = { -1, -1 };
    double length_m = 0.0; //!< measured as asked (along or horizontal)
};

/*!
  \brief The pieces of a polyline between the grid lines it crosses, each
  with the cell(s) it lies in; pieces outside the grid have no cell. Their
  lengths add up to polylineLength (round-off aside).
*/
std::vector<PolylinePiece> polylinePieces( const std::vector<Point2>& line,
                                           const GridConfig& grid,
                                           LineMeasure measure );

/*!
  \brief Each fed cell's share of the water of a polyline inflow (shares
  add up to 1; empty if no cell is fed). A piece of the line goes to its
  cell if that cell is occupied (holds an active point), a piece on a grid
  line to the occupied cells on either side (halves if both are); the
  pieces in no occupied cell (empty cells, outside the grid) are shared by
  the fed cells in proportion to their own pieces, so that the whole
  flux x length enters the soil.
*/
std::map<int, double> polylineCellShares( const std::vector<PolylinePiece>&,
                                          const std::set<int>& occupied );

//! Flat index i * ny + j of the cell holding (x, y), -1 outside the grid.
int cellIndexAt( double x, double y, const GridConfig& grid );

} // namespace mpm

#endif // MPM_POLYLINE_CELLS_HPP
