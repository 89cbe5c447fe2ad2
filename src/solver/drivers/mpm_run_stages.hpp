#ifndef MPM_RUN_STAGES_HPP
#define MPM_RUN_STAGES_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_diagnostics.hpp>
#include <records/mpm_point_fields.hpp>
#include <records/mpm_stage_state.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_static_stop.hpp>
#include <solver/mpm_host_snapshot.hpp>
#include <solver/mpm_initial_stress.hpp>
#include <solver/mpm_simulation.hpp>
#include <solver/output/mpm_run_observer.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
//! Host copy of the output's point fields of a simulation (hostSnapshot).
template <class ExecSpace>
HostSnapshot hostSnapshot( const Simulation<ExecSpace>& sim )
{
    return hostSnapshot( sim.particles, sim.water_particles );
}

//---------------------------------------------------------------------------//
//! Stage times at which snapshots are due: multiples of the interval and the
//! listed times, before the stage end (which always gets one).
class SnapshotSchedule
{
  public:
    explicit SnapshotSchedule( const StageConfig& stage )
        : _interval( stage.snapshot_interval_s )
        , _times( stage.snapshot_times_s )
        , _end( stage.duration_s * ( 1.0 - 1.0e-12 ) )
    {
    }

    //! The next due time after t (infinite if none before the stage end).
    double next( const double t ) const
    {
        double due = 1.0e300;
        if ( _interval > 0.0 )
            due = _interval *
                  ( std::floor( t / _interval * ( 1.0 + 1.0e-12 ) ) + 1.0 );
        for ( const double listed : _times )
            if ( listed > t * ( 1.0 + 1.0e-12 ) )
            {
                due = std::min( due, listed );
                break;
            }
        return due < _end ? due : 1.0e300;
    }

  private:
    double _interval;
    std::vector<double> _times;
    double _end;
};

//---------------------------------------------------------------------------//
/*!
  \brief Time over which a quasi-static stage's kinetic-energy ratio must stay
  below its tolerance: the period 4 L / c of the slowest (drained skeleton)
  wave over the bodies' extent L, c = sqrt(E_c / rho) / sqrt(inertia
  scaling), the smallest over the stage's materials. The ratio passes
  through zero at every turning point of an oscillation, so a single
  value below the tolerance does not mean equilibrium.
*/
inline double quasiStaticWindow( const CaseConfig& config,
                                 const StageConfig& stage )
{
    double x_min = 1.0e300, x_max = -1.0e300, y_min = 1.0e300, y_max = -1.0e300;
    for ( const BodyConfig& body : config.bodies )
        for ( const Point2& v : body.polygon_m )
        {
            x_min = std::min( x_min, v[0] );
            x_max = std::max( x_max, v[0] );
            y_min = std::min( y_min, v[1] );
            y_max = std::max( y_max, v[1] );
        }
    const double extent = std::max( x_max - x_min, y_max - y_min );
    double c_min = 1.0e300;
    for ( const MaterialConfig& m : stage.materials )
    {
        const double E_c =
            physics::elasticParams( m.youngs_modulus_pa, m.poisson_ratio, 0.0 )
                .constrainedModulus();
        const double rho =
            config.analysis == AnalysisType::Dry
                ? m.density_kg_per_m3
                : ( 1.0 - m.porosity ) * m.solid_density_kg_per_m3 +
                      m.porosity * config.water.density_kg_per_m3;
        c_min = std::min( c_min, std::sqrt( E_c / rho ) );
    }
    return 4.0 * extent / c_min * std::sqrt( config.solver.inertia_scaling );
}

/*!
  \brief Kinetic energy below which a quasi-static stage is at rest whatever
  its largest E_kin, J: 1e-12 E_g, E_g = 1/2 M (|g| T / 4)^2 the kinetic
  energy of the stage's gravity load (M the active points' mass, T the
  quasiStaticWindow: a body loaded by gravity from zero stress sways at
  about |g| T / 4, its settlement over a quarter period), i.e. speeds below
  a millionth of that sway. The kinetic-energy ratio is taken against the
  larger of this and the stage's largest E_kin, so a stage that starts in
  equilibrium (E_kin at rounding level: its largest E_kin is noise too)
  converges after one window, and a stage that moves is measured as before.
*/
template <class ExecSpace>
double restKineticEnergy( const Simulation<ExecSpace>& sim,
                          const StageConfig& stage, const double window_s )
{
    const auto points = unmanaged( sim.particles );
    const double mass = reduceOverActivePoints<Kokkos::Sum<double>>(
        ExecSpace(), "mpm::active_mass", sim.particles,
        KOKKOS_LAMBDA( const int p ) { return points.m_p( p ); } );
    const double sway_speed =
        std::hypot( stage.gravity_m_per_s2[0], stage.gravity_m_per_s2[1] ) *
        window_s / 4.0;
    const double rest_fraction = 1.0e-12;
    return rest_fraction * 0.5 * mass * sway_speed * sway_speed;
}

//---------------------------------------------------------------------------//
//! True if a periodic checkpoint is due at run time `time_s`.
inline bool checkpointDue( const SolverConfig& solver,
                           const StageLoopState& state, const double time_s )
{
    return solver.checkpoint_interval_s > 0.0 &&
           time_s >= state.next_checkpoint_s * ( 1.0 - 1.0e-12 );
}

//! The stage's K0 stress field (mpm_initial_stress.hpp) on sim's points.
template <class ExecSpace>
void setGeostaticStress( const StageConfig& stage, const CaseConfig& config,
                         Simulation<ExecSpace>& sim )
{
    const PointLattice lattice{
        config.grid.origin_m[0], config.grid.origin_m[1],
        config.grid.cell_size_m, config.points_per_cell_per_direction };
    setGeostaticStress( stage.initial_stress_k0, -stage.gravity_m_per_s2[1],
                        lattice, sim.materials, sim.water,
                        config.analysis == AnalysisType::Unsaturated,
                        sim.particles, sim.water_particles );
    sim.stateChanged();
}

//---------------------------------------------------------------------------//
/*!
  \brief Runs every stage of `config` on `sim`: quasi-static stages until
  E_kin / max E_kin stays below the tolerance for quasiStaticWindow (or
  their duration), dynamic stages for their duration. Snapshots at the requested
  interval and at stage ends.

  The loop starts from `state`: a fresh StageLoopState for a new run, or
  Checkpoint::loop (with `sim` restored by restoreCheckpoint) to continue
  an interrupted one. Checkpoints go to observer.onCheckpoint every
  solver.checkpoint_interval_s of run time and when stopRequested() stops
  the run; both are taken before a step, the only point a run resumes at.
  A stage's point selections that pick no point at its start go to
  observer.onWarning.
*/
template <class ExecSpace>
RunSummary runStages( Simulation<ExecSpace>& sim, const CaseConfig& config,
                      RunObserver& observer,
                      StageLoopState state = StageLoopState() )
{
    // Quasi-static stages check convergence only after this many steps.
    const long min_quasi_static_steps = 20;
    if ( state.next_checkpoint_s <= 0.0 )
        state.next_checkpoint_s = config.solver.checkpoint_interval_s;
    state.run.interrupted = false;
    RunSummary& summary = state.run;
    RunProgress& progress = state.progress;
    StageSummary& stage_summary = state.stage_summary;

    for ( ; state.stage < config.stages.size(); ++state.stage )
    {
        const StageConfig& stage = config.stages[state.stage];
        const bool quasi_static = stage.type == StageType::QuasiStatic;
        const SnapshotSchedule schedule( stage );
        if ( !state.stage_started )
        {
            sim.startStage( stage );
            if ( stage.initial_stress_k0 > 0.0 )
                setGeostaticStress( stage, config, sim );
            state.beginStage( state.stage, stage.name, stage.duration_s,
                              quasi_static, schedule.next( 0.0 ) );
            for ( const std::string& key : sim.conditions.empty_selections )
                observer.onWarning( "key 'stages[" +
                                    std::to_string( state.stage ) + "]." + key +
                                    "': selects no material point at the "
                                    "stage start" );
            const WaterContent water = sim.waterContent();
            stage_summary.water.begin( water.active, water.removed );
        }
        const StepSettings settings{ stage.gravity_m_per_s2[0],
                                     stage.gravity_m_per_s2[1], stage.damping };
        const double window_s =
            quasi_static ? quasiStaticWindow( config, stage ) : 0.0;
        const double ke_at_rest =
            quasi_static ? restKineticEnergy( sim, stage, window_s ) : 0.0;
        // Round-off of the summed steps, at most 1 ns: relative to a long
        // stage it would exceed the snapshot interval.
        const double end_tolerance =
            std::min( 1.0e-12 * stage.duration_s, 1.0e-9 );

        while ( progress.stage_time_s < stage.duration_s - end_tolerance )
        {
            if ( observer.stopRequested() )
            {
                Checkpoint checkpoint = captureCheckpoint( sim, config, state );
                observer.onCheckpoint( checkpoint );
                summary.interrupted = true;
                stage_summary.stop_reason = "interrupted";
                break;
            }
            if ( checkpointDue( config.solver, state, sim.time ) )
            {
                const double interval = config.solver.checkpoint_interval_s;
                state.next_checkpoint_s =
                    interval *
                    ( std::floor( sim.time / interval * ( 1.0 + 1.0e-12 ) ) +
                      1.0 );
                Checkpoint checkpoint = captureCheckpoint( sim, config, state );
                observer.onCheckpoint( checkpoint );
            }
            const WaveSpeedLimit limit = sim.waveSpeedLimit();
            const double dt_stable = sim.nextStep();
            // Land exactly on the stage end and on snapshot times.
            const double dt_asked = std::min(
                dt_stable, std::min( stage.duration_s, state.next_snapshot_s ) -
                               progress.stage_time_s );
            // The scheme may take a shorter step (a step given back).
            const double dt =
                sim.advance( dt_asked, settings, progress.stage_time_s );
            sim.checkStability( dt, limit );
            stage_summary.water.addStep( sim.stepWater() );

            progress.step = sim.step;
            ++progress.stage_step;
            progress.time_s = sim.time;
            progress.stage_time_s += dt;
            progress.dt_s = dt;
            progress.kinetic_energy_j = sim.kineticEnergy();
            progress.active_points = sim.numActivePoints();
            // The steps the stability rule chose: a step cut short to land
            // on a snapshot time is not a smaller stable step (the base
            // slope reported 1.1e-6 s that way against 2.6e-4 s chosen); a
            // step the scheme gave back counts as the shorter one it took.
            const double dt_chosen = dt < dt_asked ? dt : dt_stable;
            stage_summary.dt_min_s =
                std::min( stage_summary.dt_min_s, dt_chosen );
            stage_summary.dt_max_s =
                std::max( stage_summary.dt_max_s, dt_chosen );
            const double max_speed = sim.maxPointSpeed();
            stage_summary.max_speed_m_per_s =
                std::max( stage_summary.max_speed_m_per_s, max_speed );
            observer.onStep( progress );
            if ( progress.time_s >= observer.nextSampleTime() )
                observer.onSample( progress, hostSnapshot( sim ) );

            if ( progress.stage_time_s >=
                 state.next_snapshot_s - end_tolerance )
            {
                observer.onSnapshot( progress, hostSnapshot( sim ) );
                state.next_snapshot_s = schedule.next( progress.stage_time_s );
            }

            // A scheme whose steps end at rest has nothing to settle: such a
            // stage runs its duration (its flow is real time).
            if ( quasi_static && !sim.endsAtRest() )
            {
                state.ke_max =
                    std::max( state.ke_max, progress.kinetic_energy_j );
                const double ke_reference =
                    std::max( state.ke_max, ke_at_rest );
                stage_summary.ke_ratio =
                    ke_reference > 0.0
                        ? progress.kinetic_energy_j / ke_reference
                        : 0.0;
                if ( stage_summary.ke_ratio >= stage.ke_ratio_tolerance )
                    state.below_since = -1.0;
                else if ( state.below_since < 0.0 )
                    state.below_since = progress.stage_time_s;
                if ( progress.stage_step >= min_quasi_static_steps &&
                     state.below_since >= 0.0 &&
                     progress.stage_time_s - state.below_since >= window_s )
                {
                    stage_summary.converged = true;
                    stage_summary.stop_reason = "kinetic_energy_ratio";
                    break;
                }
            }
            else if ( !quasi_static && stage.static_stop.enabled() &&
                      staticAgainIf(
                          stage.static_stop,
                          [&]()
                          {
                              return speedStatisticBelow(
                                  sim, stage.static_stop, max_speed,
                                  progress.active_points );
                          },
                          progress.stage_time_s,
                          [&sim]() { return sim.maxDisplacement(); }, state ) )
            {
                stage_summary.stop_reason = "static_again";
                break;
            }
        }

        if ( quasi_static && sim.endsAtRest() && !summary.interrupted )
        {
            stage_summary.converged = true;
            stage_summary.stop_reason = "duration (each step ends at rest)";
        }
        stage_summary.steps = progress.stage_step;
        stage_summary.duration_s = progress.stage_time_s;
        const WaterContent water = sim.waterContent();
        stage_summary.water.end( water.active, water.removed );
        const HostSnapshot stage_end = hostSnapshot( sim );
        observer.onSnapshot( progress, stage_end );
        if ( !quasi_static && stage.static_stop.enabled() )
            recordSpeedStatistic( stage.static_stop, stage_end, stage_summary );
        if ( stage.reset_displacement && !summary.interrupted )
            sim.resetDisplacement();
        observer.onStageEnd( progress, stage_summary );
        summary.steps += stage_summary.steps;
        summary.dt_min_s = std::min( summary.dt_min_s, stage_summary.dt_min_s );
        summary.dt_max_s = std::max( summary.dt_max_s, stage_summary.dt_max_s );
        if ( summary.stages.empty() )
            summary.water = stage_summary.water;
        else
            summary.water.append( stage_summary.water );
        summary.stages.push_back( stage_summary );
        state.stage_started = false;
        if ( summary.interrupted )
            break;
    }
    return summary;
}

} // namespace mpm

#endif // MPM_RUN_STAGES_HPP
