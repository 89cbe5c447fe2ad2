#ifndef MPM_SIMULATION_HPP
#define MPM_SIMULATION_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_step_scheme.hpp>

#include <algorithm>
#include <cmath>
#include <variant>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief One simulation: its state (SimulationState: points, grid,
  materials, conditions) and the step scheme that advances it, chosen once
  from the case (makeStepScheme: the dry step, the explicit,
  semi-implicit, seepage, quasi-static or auto two-phase step;
  solver/steps).
*/
template <class ExecSpace>
class Simulation : public SimulationState<ExecSpace>
{
  public:
    //! Generates the points of `config`, applies its first stage and
    //! builds the step scheme of its scene and [solver].
    explicit Simulation( const CaseConfig& config )
        : SimulationState<ExecSpace>( config )
        , _scheme( makeStepScheme<ExecSpace>( *this ) )
    {
    }

    //! The step scheme's name as the case file writes it.
    const char* schemeName() const
    {
        return std::visit( []( const auto& s ) { return s.scheme; }, _scheme );
    }

    //! True if each of the scheme's steps ends at rest (seepage,
    //! quasi-static, auto while quasi-static).
    bool endsAtRest() const
    {
        return std::visit( []( const auto& s ) { return s.ends_at_rest; },
                           _scheme );
    }

    //! Water held by the points now, the scheme's water in transit among
    //! the active points' (zero in a dry scene).
    WaterContent waterContent() const
    {
        WaterContent content = SimulationState<ExecSpace>::waterContent();
        content.active += std::visit(
            []( const auto& s ) { return s.waterInTransit(); }, _scheme );
        return content;
    }

    //! How the scheme chooses its step (solver.dt_s fixed or not).
    const char* stepRule() const
    {
        const bool fixed = this->solver.dt_s > 0.0;
        return std::visit( [fixed]( const auto& s )
                           { return fixed ? s.fixed_step : s.automatic_step; },
                           _scheme );
    }

    //! The step the scheme takes next (its nextStep at the CFL limit of
    //! the state now); throws SimulationError for a fixed solver.dt_s
    //! above the CFL limit of a scheme that has one.
    double nextStep() const
    {
        const WaveSpeedLimit limit = waveSpeedLimit();
        return std::visit( [&]( const auto& s )
                           { return s.nextStep( *this, limit ); },
                           _scheme );
    }

    //! The wave whose speed limits the scheme's step.
    const char* limitingWave() const
    {
        return std::visit( []( const auto& s ) { return s.limiting_wave; },
                           _scheme );
    }

    //! The pressure solves so far (the schemes with one), else null.
    const PressureSolveStats* pressureSolveStats() const
    {
        return std::visit(
            []( const auto& s ) { return s.pressureSolveStats(); }, _scheme );
    }

    //! The relaxations so far (quasi-static), else null.
    const RelaxationStats* relaxationStats() const
    {
        return std::visit( []( const auto& s ) { return s.relaxationStats(); },
                           _scheme );
    }

    //! CFL limit (Courant number 1) and the largest wave speed of the
    //! scheme's fastest wave, both of the inertia-scaled system (waves
    //! sqrt(f) slower): the last step's diagnostics while they are current.
    WaveSpeedLimit waveSpeedLimit() const
    {
        WaveSpeedLimit limit =
            this->diagnosticsCurrent()
                ? this->diagnosedLimit()
                : std::visit( [this]( const auto& s )
                              { return s.cflLimit( *this ); },
                              _scheme );
        const double root_f = std::sqrt( this->solver.inertia_scaling );
        limit.dt_limit *= root_f;
        limit.max_wave_speed /= root_f;
        return limit;
    }

    //! The auto scheme's switches and steps per scheme, or null.
    const AutoStats* autoStats() const
    {
        const auto* automatic = std::get_if<AutoStep<ExecSpace>>( &_scheme );
        return automatic ? &automatic->stats() : nullptr;
    }

    //! Applies `stage`'s conditions (SimulationState::applyStage) and
    //! starts the scheme's steps of the stage (a flow's from
    //! solver.seepage_initial_dt_s).
    void startStage( const StageConfig& stage )
    {
        this->applyStage( stage );
        std::visit( [this]( auto& s ) { s.startStage( this->solver ); },
                    _scheme );
    }

    //! The steps the scheme gave back and took again, shorter, so far.
    long stepsRetaken() const
    {
        return std::visit( []( const auto& s ) { return s.stepsRetaken(); },
                           _scheme );
    }

    /*!
      \brief One step of the scheme at stage time stage_time_s, of size dt
      or, if the scheme gives the step back (the auto scheme hands off to
      dynamics, or a flow changed a saturation too much), of the scheme's
      next step if shorter; returns the step taken. Throws
      SimulationError if a point leaves the grid (unless removal is
      enabled).
    */
    double advance( double dt, const StepSettings& settings,
                    const double stage_time_s = 0.0 )
    {
        PointUpdateReport report = stepOnce( dt, settings, stage_time_s );
        while ( stepGivenBack() )
        {
            dt = std::min( dt, nextStep() );
            report = stepOnce( dt, settings, stage_time_s );
        }
        this->stepTaken( dt, report );
        if ( report.first_outside >= 0 )
            throw SimulationError( this->describe(
                report.first_outside,
                "left the grid (set solver.remove_points_leaving_grid "
                "= true to remove such points instead)" ) );
        return dt;
    }

  private:
    //! True if the scheme's last advance took no step.
    bool stepGivenBack() const
    {
        return std::visit( []( const auto& s ) { return s.stepGivenBack(); },
                           _scheme );
    }

    //! The scheme's step dt, the conditions over it (at its end; the
    //! inflows at their mean over it).
    PointUpdateReport stepOnce( const double dt, const StepSettings& settings,
                                const double stage_time_s )
    {
        this->conditions.update( stage_time_s, stage_time_s + dt );
        const WaveSpeedLimit limit = waveSpeedLimit();
        return std::visit( [&]( auto& s )
                           { return s.advance( *this, dt, settings, limit ); },
                           _scheme );
    }

    StepScheme<ExecSpace> _scheme;
};

} // namespace mpm

#endif // MPM_SIMULATION_HPP
