#include <setup/mpm_base_slivers.hpp>
#include <setup/mpm_conditions.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_stage_flags.hpp>

namespace mpm
{
StageNodeFlags stageNodeFlags( const GridConfig& grid_config,
                               const physics::GridGeometry& grid,
                               const StageConfig& stage, const bool two_phase,
                               const bool complete_base,
                               const std::vector<double>& x )
{
    StageNodeFlags flags;
    flags.solid =
        nodeFlags( grid_config, interiorWalls( stage.boundaries, false ) );
    if ( two_phase )
        flags.water = waterNodeFlags( grid_config, stage.boundaries );
    // (A restart re-applies the stage before it restores the flags: the
    // slivers found then do not matter.)
    if ( complete_base )
    {
        flags.cut_cells = cutBaseCells( grid_config, stage.boundaries );
        fixBaseSlivers( grid, x, flags.cut_cells, flags.solid, &flags.water );
    }
    const std::vector<int> walls =
        nodeFlags( grid_config, interiorWalls( stage.boundaries, true ) );
    for ( std::size_t n = 0; n < flags.solid.size(); ++n )
        flags.solid[n] |= walls[n];
    return flags;
}

} // namespace mpm
