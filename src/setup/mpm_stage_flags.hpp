#ifndef MPM_STAGE_FLAGS_HPP
#define MPM_STAGE_FLAGS_HPP

#include <case/mpm_case_config.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <vector>

namespace mpm
{
//! The node flags of a stage (NodeFlag per node, index i * (ny + 1) + j).
struct StageNodeFlags
{
    std::vector<int> solid;     //!< the solid's fixities and walls
    std::vector<int> water;     //!< the water's (empty in a dry scene)
    std::vector<int> cut_cells; //!< cells cut by the base (cutBaseCells)
};

/*!
  \brief The node flags of `stage`'s boundaries. Two-phase (`two_phase`)
  also the water's; with `complete_base` (solver.base_cell_completion in a
  two-phase scene) the cells cut by the fixed base and the fixed slivers
  among them (fixBaseSlivers, with the points at `x`: x, y per point, m).
  Interior walls are added after the slivers: the empty cells beside a
  wall are no soil sliver (they would all be fixed).
*/
StageNodeFlags stageNodeFlags( const GridConfig& grid_config,
                               const physics::GridGeometry& grid,
                               const StageConfig& stage, bool two_phase,
                               bool complete_base,
                               const std::vector<double>& x );

} // namespace mpm

#endif // MPM_STAGE_FLAGS_HPP
