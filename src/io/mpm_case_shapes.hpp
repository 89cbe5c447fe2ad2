#ifndef MPM_CASE_SHAPES_HPP
#define MPM_CASE_SHAPES_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Checks of the shapes in a case file. Internal to the case reader.
//---------------------------------------------------------------------------//

/*!
  \brief Check a body polygon read from node (an array of points) at path:
  at least 3 distinct vertices, no repeated consecutive vertex, no
  self-intersection and, if grid is given, every vertex inside the grid.

  A repeated closing vertex is removed from polygon.
*/
void checkBodyPolygon( std::vector<Point2>& polygon, const toml::node& node,
                       const std::string& path, const GridConfig* grid,
                       Diagnostics& diag );

//---------------------------------------------------------------------------//
//! \brief "" if point lies inside the grid (up to round-off), else the text
//! "inside the grid, x in [..] m and y in [..] m (...), found [x, y] m".
std::string outsideGridText( const GridConfig& grid, const Point2& point );

//---------------------------------------------------------------------------//
/*!
  \brief Warn (not an error) if points of a polyline read from node lie
  outside the grid: one warning at the first such point, counting them,
  with `consequence` (what the line does there) appended.
*/
void warnPolylineOutsideGrid( const std::vector<Point2>& line,
                              const toml::node& node, const std::string& path,
                              const GridConfig& grid,
                              const std::string& consequence,
                              Diagnostics& diag );

//---------------------------------------------------------------------------//
//! \brief Check that the x of a boundary polyline increase strictly.
void checkPolyline( const std::vector<Point2>& line, const toml::node& node,
                    const std::string& path, Diagnostics& diag );

//---------------------------------------------------------------------------//
/*!
  \brief Check an interior wall's polyline (where = "polyline"): no
  repeated consecutive vertex and, if grid is given, every vertex inside
  the grid. Any direction; vertical segments are allowed.
*/
void checkWallPolyline( const std::vector<Point2>& line, const toml::node& node,
                        const std::string& path, const GridConfig* grid,
                        Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_SHAPES_HPP
