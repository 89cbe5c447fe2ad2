#ifndef MPM_BASE_SLIVERS_HPP
#define MPM_BASE_SLIVERS_HPP

#include <case/mpm_case_config.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <vector>

namespace mpm
{
/*!
  \brief Fixes the free nodes of cells that have a fixed node (NodeFlag
  node_fixed) but no material point: the soil there is a sliver between
  the base line and the grid, thinner than the points' spacing from the
  cell's edge, which nothing represents. Without it a node just above the
  base line rested on an empty cell: nothing held it, and its water (and
  solid) fell into the base (a point next to it reached a relative water
  velocity of 0.9 m/s in 24 ms). Such a node takes the solid flag
  node_fixed and the water flags of the cell's fixed nodes, so the base
  follows the staircase of fixed nodes there (at most a point spacing
  higher). Repeats until no cell changes. Only cells the base line cuts
  (`cut_cells`, cutBaseCells) can hold a sliver: an empty cell beside a
  fixed grid edge or wall is empty space (fixing it spread fixed nodes
  through the whole empty grid above a fixed floor, so nothing could run
  out there). `x` holds the points' positions (x, y per point, m);
  `water_flags` may be null (dry scenes).
  \return the number of nodes fixed.
*/
int fixBaseSlivers( const physics::GridGeometry& grid,
                    const std::vector<double>& x,
                    const std::vector<int>& cut_cells, std::vector<int>& flags,
                    std::vector<int>* water_flags );

/*!
  \brief The cells a fixed `below_polyline` boundary line passes through
  (strictly inside: a line on a grid line cuts no cell), as a flag per cell
  (index ci * ny + cj): the cells physics::BaseCellCompletion completes.
  From the case alone, so a restarted run finds the same cells.
*/
std::vector<int> cutBaseCells( const GridConfig& grid,
                               const std::vector<BoundaryConfig>& boundaries );

} // namespace mpm

#endif // MPM_BASE_SLIVERS_HPP
