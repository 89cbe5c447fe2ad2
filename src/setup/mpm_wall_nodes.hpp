#ifndef MPM_WALL_NODES_HPP
#define MPM_WALL_NODES_HPP

#include <case/mpm_case_config.hpp>

#include <vector>

namespace mpm
{
/*!
  \brief The grid nodes an interior wall (a `where = "polyline"` boundary)
  holds, as a flag per node (flat index i * (ny + 1) + j; 1 = selected).

  Rule: a node is selected when the polyline passes less than one cell
  size h from it along both grid axes (its max-norm distance to some
  segment is < h), i.e. when the node's bilinear shape function is not
  zero somewhere on the wall. Distances within 1e-9 h of h count as h (not
  selected), so a wall on a grid line selects that line's nodes only.

  Guarantee: at every point of the wall every node with a non-zero weight
  is selected, so the grid velocity interpolated anywhere on the wall is
  the wall's (zero for a fixed wall) whatever the free nodes carry; no
  material point can reach the wall line, let alone cross it, at a stable
  step, and there is no gap however the wall meets the grid. In cell terms:
  every cell whose interior the wall crosses has its four corners
  selected, and a wall along a grid line selects that line's nodes. The
  set is the smallest with that property (a node farther away has a zero
  weight on the whole wall). A wall on a grid line holds one line of
  nodes; a wall between grid lines, or a diagonal one, the corners of the
  cells it crosses (the points in those cells are held with the wall).

  Vertices outside the grid select the nodes near the part inside it.
*/
std::vector<int> wallNodes( const GridConfig& grid,
                            const std::vector<Point2>& polyline );

} // namespace mpm

#endif // MPM_WALL_NODES_HPP
