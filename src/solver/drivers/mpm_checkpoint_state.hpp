#ifndef MPM_CHECKPOINT_STATE_HPP
#define MPM_CHECKPOINT_STATE_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>
#include <records/mpm_stage_state.hpp>
#include <solver/mpm_simulation.hpp>
#include <solver/mpm_simulation_error.hpp>

#include <Kokkos_Core.hpp>

#include <string>
#include <type_traits>

namespace mpm
{
//---------------------------------------------------------------------------//
// The Views a checkpoint holds: every View of the point and grid structs
// (each struct's forEachViewOf in views/). A View added to one of these
// structs must be added to its list (the test
// Restart.checkpoint_lists_every_point_view checks the point structs). Grid
// Views are mostly rebuilt every step, but v_i / dv_i keep their values on
// nodes that lost their mass and the velocity gradient reads them, so all are
// kept to make a restart exact.

//! Calls f("<group>/<view>", view) for every View of the simulation's
//! state (water groups only in two-phase scenes). Sim may be const.
template <class Sim, class F>
void forEachStateView( Sim& sim, F&& f )
{
    const auto in = [&]( const std::string& group )
    {
        return [&f, group]( const char* name, auto& view )
        { f( group + "/" + name, view ); };
    };
    forEachView( sim.particles, in( "particles" ) );
    forEachView( sim.grid, in( "grid" ) );
    if ( sim.twoPhase() )
    {
        forEachView( sim.water_particles, in( "water" ) );
        forEachView( sim.water_grid, in( "water_grid" ) );
    }
}

//---------------------------------------------------------------------------//
//! Host copy of a View (row-major, its extents).
template <class View>
CheckpointArray toCheckpointArray( const std::string& name, const View& view )
{
    CheckpointArray a;
    a.name = name;
    for ( unsigned r = 0; r < View::rank; ++r )
        a.dims.push_back( view.extent( r ) );
    const auto host =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
    using Value = typename View::non_const_value_type;
    static_assert( std::is_same_v<Value, double> || std::is_same_v<Value, int>,
                   "checkpoint arrays are double or int" );
    if constexpr ( std::is_same_v<Value, int> )
    {
        a.integer = true;
        a.integers.assign( host.data(), host.data() + host.span() );
    }
    else
        a.reals.assign( host.data(), host.data() + host.span() );
    return a;
}

//! Copies a checkpoint array into a View of the same extents.
template <class View>
void fromCheckpointArray( const CheckpointArray& a, const View& view )
{
    using Value = typename View::non_const_value_type;
    bool same =
        a.dims.size() == View::rank && a.integer == std::is_same_v<Value, int>;
    for ( unsigned r = 0; same && r < View::rank; ++r )
        same = a.dims[r] == view.extent( r );
    if ( !same )
        throw SimulationError( "checkpoint array '" + a.name +
                               "' does not fit the simulation's View (other "
                               "extents or type)" );
    auto host = Kokkos::create_mirror_view( view );
    if constexpr ( std::is_same_v<Value, int> )
        std::copy( a.integers.begin(), a.integers.end(), host.data() );
    else
        std::copy( a.reals.begin(), a.reals.end(), host.data() );
    Kokkos::deep_copy( view, host );
}

//---------------------------------------------------------------------------//
inline std::string analysisName( const AnalysisType analysis )
{
    switch ( analysis )
    {
    case AnalysisType::Dry:
        return "dry";
    case AnalysisType::Saturated:
        return "saturated";
    case AnalysisType::Unsaturated:
        return "unsaturated";
    }
    return "unknown";
}

//! What a checkpoint of this run is written for.
template <class ExecSpace>
CheckpointIdentity checkpointIdentity( const CaseConfig& config,
                                       const Simulation<ExecSpace>& sim )
{
    CheckpointIdentity id;
    id.case_name = config.name;
    id.case_file = config.file;
    id.case_fingerprint = config.fingerprint;
    id.analysis = analysisName( config.analysis );
    id.num_points = sim.particles.size();
    id.backend = ExecSpace::name();
    id.threads = ExecSpace::concurrency();
    return id;
}

//---------------------------------------------------------------------------//
/*!
  \brief Host copy of the whole state of a run: the simulation and the
  stage-loop state `loop` (the outputs' part, Checkpoint::snapshots and
  wall_s, is filled in by whoever writes the outputs).
*/
template <class ExecSpace>
Checkpoint captureCheckpoint( const Simulation<ExecSpace>& sim,
                              const CaseConfig& config,
                              const StageLoopState& loop )
{
    Kokkos::fence();
    Checkpoint c;
    c.identity = checkpointIdentity( config, sim );
    c.time_s = sim.time;
    c.step = sim.step;
    c.num_removed = sim.num_removed;
    c.grid_num_active = sim.grid.num_active;
    forEachStateView( sim,
                      [&]( const std::string& name, const auto& view ) {
                          c.arrays.push_back( toCheckpointArray( name, view ) );
                      } );
    c.load_counts = sim.conditions.load_counts;
    c.load_groups = sim.conditions.load_groups;
    c.inflow_volumes = sim.conditions.inflow_volumes;
    for ( const WaterInflow& inflow : sim.conditions.inflows )
        c.inflow_lengths_m.push_back( inflow.length_m );
    c.next_surface_update_s = sim.conditions.next_surface_update_s;
    c.loop = loop;
    return c;
}

/*!
  \brief Puts `sim` (freshly constructed from `config`, which the
  checkpoint must match: checkpointMismatch) into the checkpoint's state.
  The current stage's materials and boundary flags come from the case;
  its point conditions (which points carry a load, a prescribed pore
  pressure or an inflow) are the ones chosen at the stage start, restored
  from the checkpoint, not selected again. runStages then continues from
  `checkpoint.loop`.
*/
template <class ExecSpace>
void restoreCheckpoint( Simulation<ExecSpace>& sim, const CaseConfig& config,
                        const Checkpoint& checkpoint )
{
    const StageLoopState& loop = checkpoint.loop;
    if ( checkpoint.identity.num_points != sim.particles.size() ||
         loop.stage >= config.stages.size() )
        throw SimulationError(
            "checkpoint does not fit the case (number of points or stage)" );
    if ( loop.stage_started )
        sim.applyStage( config.stages[loop.stage] );
    forEachStateView( sim,
                      [&]( const std::string& name, const auto& view )
                      {
                          const CheckpointArray* a = checkpoint.find( name );
                          if ( !a )
                              throw SimulationError(
                                  "checkpoint lacks the array '" + name +
                                  "' (written by another version?)" );
                          fromCheckpointArray( *a, view );
                      } );
    sim.flagsRestored();
    if ( loop.stage_started )
    {
        StageConditions<ExecSpace>& conditions = sim.conditions;
        const std::size_t num_inflows = conditions.inflows.size();
        if ( checkpoint.inflow_volumes.size() != num_inflows ||
             checkpoint.inflow_lengths_m.size() != num_inflows ||
             checkpoint.load_counts.size() != conditions.loads.size() )
            throw SimulationError( "checkpoint conditions do not fit the "
                                   "stage's loads or inflows" );
        // Every host-side member of StageConditions that changes after
        // apply() (a new one must be added here and to Checkpoint).
        conditions.load_counts = checkpoint.load_counts;
        conditions.load_groups = checkpoint.load_groups;
        conditions.inflow_volumes = checkpoint.inflow_volumes;
        for ( std::size_t f = 0; f < num_inflows; ++f )
            conditions.inflows[f].length_m = checkpoint.inflow_lengths_m[f];
        conditions.next_surface_update_s = checkpoint.next_surface_update_s;
        conditions.load_force = LoadForceView<ExecSpace>(
            "load_force", conditions.load_groups.size() );
        conditions.update( loop.progress.stage_time_s,
                           loop.progress.stage_time_s );
    }
    sim.time = checkpoint.time_s;
    sim.step = checkpoint.step;
    sim.num_removed = checkpoint.num_removed;
    sim.grid.num_active = checkpoint.grid_num_active;
    // The point fields were written directly: drop what the simulation
    // derived from the old ones.
    sim.stateChanged();
}

} // namespace mpm

#endif // MPM_CHECKPOINT_STATE_HPP
