#ifndef MPM_AUTO_STEP_HPP
#define MPM_AUTO_STEP_HPP

#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_auto_stats.hpp>
#include <solver/steps/mpm_pressure_solve_stats.hpp>
#include <solver/steps/mpm_quasi_static_step.hpp>
#include <solver/steps/mpm_semi_implicit_step.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The auto scheme (docs/formulation.md §12): the quasi-static
  scheme while the skeleton finds its equilibrium in every step, the
  semi-implicit scheme while it does not. A quasi-static step whose
  relaxation does not come to rest (the soil is failing) is taken back: the
  points go back to the step's start, the last equilibrium, and the
  semi-implicit scheme follows the failure from there, so the slide starts
  when the dynamics say it does, within the quasi-static step. From the
  end of that step on, once the fastest point has stayed slower than
  solver.auto_rest_speed_m_per_s for solver.auto_rest_window_s,
  quasi-static steps take over again, from the
  last dynamic step, doubling. The quasi-static scheme's water in transit
  waits through the dynamic steps and is given to the points by its next
  flow. The permeability is the material's throughout.
*/
template <class ExecSpace>
class AutoStep
{
  public:
    static constexpr const char* scheme = "auto";
    static constexpr const char* automatic_step =
        "automatic: the quasi-static scheme's (the flow's saturation change) "
        "while the skeleton finds its equilibrium, the semi-implicit "
        "scheme's (courant_number x the skeleton's CFL limit) while it "
        "moves";
    static constexpr const char* fixed_step = "fixed dt_s";
    static constexpr const char* limiting_wave =
        "none while quasi-static; the skeleton's P wave while dynamic";

    //! True while the quasi-static scheme runs (each step ends at rest).
    bool ends_at_rest = true;

    explicit AutoStep( const SimulationState<ExecSpace>& state )
        : _quasi_static( state )
        , _dynamic( state )
    {
    }

    //! A stage starts: the quasi-static steps start again from
    //! solver.seepage_initial_dt_s.
    void startStage( const SolverConfig& solver )
    {
        _quasi_static.startStage( solver );
    }

    //! The CFL limit of the skeleton's P wave (both schemes').
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return _dynamic.cflLimit( s );
    }

    //! The next step of the scheme that runs.
    double nextStep( const SimulationState<ExecSpace>& s,
                     const WaveSpeedLimit& limit ) const
    {
        return ends_at_rest ? _quasi_static.nextStep( s, limit )
                            : _dynamic.nextStep( s, limit );
    }

    /*!
      \brief One step of the scheme that runs. A quasi-static step whose
      skeleton finds no equilibrium leaves the state as it was, hands off to
      the semi-implicit scheme and returns with stepGivenBack() true: the
      caller takes the step again, at the semi-implicit scheme's nextStep.
      So does a quasi-static step whose flow changed a saturation too much,
      to be taken again at the quasi-static scheme's shorter nextStep.
    */
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        _given_back = false;
        const auto start = std::chrono::steady_clock::now();
        const auto elapsed = [&start]()
        {
            return std::chrono::duration<double>(
                       std::chrono::steady_clock::now() - start )
                .count();
        };
        if ( ends_at_rest )
        {
            const double chosen = _quasi_static.nextStep( s, limit );
            const QuasiStaticAttempt step =
                _quasi_static.attempt( s, dt, settings, limit );
            _stats.quasi_static.wall_s += elapsed();
            _given_back = step.given_back;
            if ( step.given_back )
                return PointUpdateReport();
            if ( step.at_rest && step.report.first_outside < 0 )
            {
                _stats.quasi_static.add( chosen );
                return step.report;
            }
            _quasi_static.restoreStepStart( s );
            handOff( s, dt, step.relaxed );
            return PointUpdateReport();
        }
        const double chosen = _dynamic.nextStep( s, limit );
        const PointUpdateReport report =
            _dynamic.advance( s, dt, settings, limit );
        _stats.dynamic.wall_s += elapsed();
        _stats.dynamic.add( chosen );
        takeBackIfAtRest( s, dt, report );
        return report;
    }

    //! True if the last advance took no step (a hand-off to the
    //! semi-implicit scheme, or a quasi-static step given back): the caller
    //! takes it again at nextStep.
    bool stepGivenBack() const { return _given_back; }

    //! The quasi-static steps given back so far.
    long stepsRetaken() const { return _quasi_static.stepsRetaken(); }

    //! The pressure solves of both schemes so far.
    const PressureSolveStats* pressureSolveStats() const
    {
        _solves = *_quasi_static.pressureSolveStats();
        _solves.add( *_dynamic.pressureSolveStats() );
        return &_solves;
    }

    //! The quasi-static scheme's relaxations so far.
    const RelaxationStats* relaxationStats() const
    {
        return _quasi_static.relaxationStats();
    }

    //! The quasi-static scheme's water in transit, m^3 per metre (held
    //! while the semi-implicit scheme runs).
    double waterInTransit() const { return _quasi_static.waterInTransit(); }

    //! The switches, steps and wall time of each scheme so far.
    const AutoStats& stats() const { return _stats; }

  private:
    //! Hands off to the semi-implicit scheme at `s`'s time, after a
    //! quasi-static step dt whose relaxation did not come to rest.
    void handOff( const SimulationState<ExecSpace>& s, const double dt,
                  const RelaxationReport& relaxed )
    {
        std::ostringstream reason;
        reason << "no equilibrium over a quasi-static step of " << dt
               << " s: after " << relaxed.steps
               << " relaxation steps the fastest point moved at "
               << relaxed.max_speed << " m/s";
        if ( relaxed.last.first_outside >= 0 )
            reason << " and a point left the grid";
        _stats.switches.push_back( { s.time, _dynamic.scheme, reason.str() } );
        ends_at_rest = false;
        _given_back = true;
        _rest_since_s = -1.0;
        _dynamic_until_s = s.time + dt;
    }

    //! After a dynamic step dt (`report`): back to quasi-static steps once
    //! the fastest point has stayed below the rest speed for the window.
    void takeBackIfAtRest( const SimulationState<ExecSpace>& s, const double dt,
                           const PointUpdateReport& report )
    {
        const double now = s.time + dt;
        const double speed = std::sqrt( report.diagnostics.max_speed2 );
        if ( now < _dynamic_until_s ||
             !( speed < s.solver.auto_rest_speed_m_per_s ) )
        {
            _rest_since_s = -1.0;
            return;
        }
        if ( _rest_since_s < 0.0 )
            _rest_since_s = now;
        if ( now - _rest_since_s < s.solver.auto_rest_window_s )
            return;
        std::ostringstream reason;
        reason << "at rest: the fastest point slower than "
               << s.solver.auto_rest_speed_m_per_s << " m/s for "
               << now - _rest_since_s << " s";
        _stats.switches.push_back(
            { now, _quasi_static.scheme, reason.str() } );
        ends_at_rest = true;
        _quasi_static.resumeAfter( dt );
    }

    QuasiStaticStep<ExecSpace> _quasi_static;
    SemiImplicitStep<ExecSpace> _dynamic;
    AutoStats _stats;
    mutable PressureSolveStats _solves;
    bool _given_back = false;
    double _rest_since_s = -1.0; //!< since when the points are at rest
    //! The end of the quasi-static step given up: the dynamic steps run at
    //! least to it (its pore pressures found no equilibrium).
    double _dynamic_until_s = 0.0;
};

} // namespace mpm

#endif // MPM_AUTO_STEP_HPP
