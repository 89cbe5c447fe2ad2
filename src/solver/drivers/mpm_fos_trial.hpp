#ifndef MPM_FOS_TRIAL_HPP
#define MPM_FOS_TRIAL_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_fos_bbar.hpp>
#include <solver/drivers/mpm_fos_criterion.hpp>
#include <solver/drivers/mpm_run_stages.hpp>
#include <solver/mpm_simulation.hpp>
#include <solver/output/mpm_progress.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace mpm
{
//! Thrown by a trial at its next step once Ctrl-C (SIGINT/SIGTERM) is
//! requested: the search stops there and writes no result.
struct FosInterrupted : std::runtime_error
{
    explicit FosInterrupted( const double factor )
        : std::runtime_error( "interrupted in the trial at F = " +
                              std::to_string( factor ) )
    {
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The stage a strength-reduction trial runs: stage `base` of the
  case (its gravity, boundaries and loads) with every material's strength
  divided by `factor` (reducedStrength), no inflow, no static stop, and,
  in a two-phase scene, every point's p_w held at its value at the trial
  start (so S and the suction are frozen too) and the water locked to the
  skeleton (permeability 0): a reduction with given pore pressures, whose
  gradient still loads the skeleton through the mixture's balance. Free
  water would flow through the held field, which is not in equilibrium
  (an infiltrating front), and its drag kept the skeleton drifting at
  1e-5 - 1e-4 m/s at every F (docs/slope-study.md, "The failure
  criterion").
*/
inline StageConfig fosTrialStage( const StageConfig& base, const bool two_phase,
                                  const double factor, const double damping )
{
    StageConfig stage = base;
    stage.name = "fos_trial";
    stage.type = StageType::Dynamic;
    stage.damping = damping;
    stage.static_stop = StaticStop();
    stage.snapshot_interval_s = 0.0;
    stage.snapshot_times_s.clear();
    stage.reset_displacement = false;
    stage.initial_stress_k0 = 0.0; // a trial starts from the saved stress
    stage.inflows.clear();
    stage.pore_pressures.clear();
    if ( two_phase )
    {
        PorePressureCondition hold;
        hold.points.kind = PointSelection::Kind::All;
        hold.hold_initial = true;
        stage.pore_pressures.push_back( hold );
    }
    for ( MaterialConfig& m : stage.materials )
    {
        m = reducedStrength( m, factor );
        if ( two_phase )
            m.permeability_m2 = 0.0;
    }
    return stage;
}

//---------------------------------------------------------------------------//
//! The kinetic energy of a trial: its peak and its mean over the last
//! quarter (time-weighted), for FosTrialRecord::ke_ratio.
struct TrialKineticEnergy
{
    double peak = 0.0;
    double last = 0.0;
    double late_integral = 0.0; //!< integral of E_kin dt in the last quarter
    double late_time = 0.0;

    void add( const double ke, const double dt, const bool late )
    {
        peak = std::max( peak, ke );
        last = ke;
        if ( late )
        {
            late_integral += ke * dt;
            late_time += dt;
        }
    }

    //! Mean over the last quarter (the last value if the trial stopped
    //! before it) over the peak.
    double ratio() const
    {
        const double late = late_time > 0.0 ? late_integral / late_time : last;
        return peak > 0.0 ? late / peak : 0.0;
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Runs strength-reduction trials on a simulation: each trial starts
  from the same state, the one `sim` holds when the runner is made (a
  host copy of every point and grid View), never from the previous
  trial, and is judged by the FosCriterion.
*/
template <class ExecSpace>
class FosTrialRunner
{
  public:
    FosTrialRunner( Simulation<ExecSpace>& sim, const CaseConfig& config,
                    const std::size_t base_stage,
                    const FosCriterion& criterion )
        : _sim( sim )
        , _config( config )
        , _base( config.stages.at( base_stage ) )
        , _criterion( criterion )
        , _initial( captureCheckpoint( sim, config, StageLoopState() ) )
    {
    }

    //! Simulated duration of a trial, s (criterion.periods x the period
    //! of the slowest skeleton wave).
    double duration() const
    {
        return _criterion.periods * quasiStaticWindow( _config, _base );
    }

    /*!
      \brief One trial at strength-reduction factor `factor`. With
      `end_state`, the points at the trial's end are copied into it.
    */
    FosTrialRecord run( const double factor, HostSnapshot* end_state = nullptr )
    {
        const auto start = std::chrono::steady_clock::now();
        FosTrialRecord record;
        record.factor = factor;
        // B-bar unless the case sets solver.bbar: at psi = 0 the volumetric
        // locking of the plain point update holds the failing soil up (the
        // Griffiths-Lane slope: FS 1.656 against 1.394).
        const BbarForTrial bbar( _sim.solver, _config.solver );
        restoreInitialState();
        // After the restore: the held p_w are the initial state's.
        _sim.applyStage( fosTrialStage( _base, _sim.twoPhase(), factor,
                                        _criterion.damping ) );
        _sim.resetDisplacement();
        if ( _sim.twoPhase() ) // the locked water starts with the skeleton
            Kokkos::deep_copy( _sim.water_particles.v_w_p, _sim.particles.v_p );
        _sim.stateChanged();
        const StepSettings settings{ _base.gravity_m_per_s2[0],
                                     _base.gravity_m_per_s2[1],
                                     _criterion.damping };
        const double total = duration();
        double t = 0.0;
        TrialKineticEnergy energy;
        const int num_samples = 20;
        const int three_quarters_sample = 15; // at 3/4 of the trial
        int next_sample = 1;
        // Past sample 15 the last quarter has begun.
        const auto in_last_quarter = [&]
        { return next_sample > three_quarters_sample; };
        const auto sample = [&]()
        {
            record.history.push_back(
                { t, _sim.maxDisplacement(), _sim.kineticEnergy(),
                  _sim.movedArea( _criterion.creep_limit_m ) } );
        };
        // The displacement limit is checked every few steps (a reduction).
        const long check_every = 10;
        try
        {
            while ( t < total * ( 1.0 - 1.0e-12 ) )
            {
                if ( interruptRequested() )
                    throw FosInterrupted( factor );
                const WaveSpeedLimit limit = _sim.waveSpeedLimit();
                const double dt =
                    std::min( chooseTimeStep( _sim.solver, limit ), total - t );
                _sim.advance( dt, settings, t );
                _sim.checkStability( dt, limit );
                t += dt;
                ++record.steps;
                energy.add( _sim.kineticEnergy(), dt, in_last_quarter() );
                if ( t >=
                     next_sample * total / num_samples * ( 1.0 - 1.0e-12 ) )
                {
                    sample();
                    if ( next_sample == three_quarters_sample )
                        record.u_three_quarters_m =
                            record.history.back().u_max_m;
                    ++next_sample;
                }
                if ( record.steps % check_every == 0 &&
                     _sim.maxDisplacement() > _criterion.displacement_limit_m )
                    break;
            }
        }
        catch ( const SimulationError& error )
        {
            record.error = error.what();
        }
        if ( record.history.empty() || record.history.back().t_s < t )
            sample(); // the trial stopped early
        record.duration_s = t;
        record.u_max_m = _sim.maxDisplacement();
        if ( !in_last_quarter() )
            record.u_three_quarters_m = record.u_max_m;
        record.ke_ratio = energy.ratio();
        judgeTrial( _criterion, record );
        if ( end_state )
            *end_state = hostSnapshot( _sim );
        record.wall_s = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start )
                            .count();
        return record;
    }

  private:
    //! Every state View, the time, step and counters of the initial state.
    void restoreInitialState()
    {
        forEachStateView(
            _sim, [&]( const std::string& name, const auto& view )
            { fromCheckpointArray( *_initial.find( name ), view ); } );
        _sim.time = _initial.time_s;
        _sim.step = _initial.step;
        _sim.num_removed = _initial.num_removed;
        _sim.grid.num_active = _initial.grid_num_active;
        _sim.stateChanged();
    }

    Simulation<ExecSpace>& _sim;
    const CaseConfig& _config;
    StageConfig _base;
    FosCriterion _criterion;
    Checkpoint _initial;
};

} // namespace mpm

#endif // MPM_FOS_TRIAL_HPP
