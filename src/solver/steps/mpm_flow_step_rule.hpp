#ifndef MPM_FLOW_STEP_RULE_HPP
#define MPM_FLOW_STEP_RULE_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_error.hpp>

#include <algorithm>
#include <sstream>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief What the schemes whose step the flow sets share (StepScheme: the
  seepage and quasi-static schemes): after a step dt in which the largest
  change of a point's saturation was dS, the next is dt
  solver.seepage_saturation_change / dS, at most twice the last one
  (solver.seepage_initial_dt_s at the start of every stage; a fixed
  solver.dt_s if given). A step that changed a saturation by more than
  retake_factor x the target is given back (the scheme restores the state
  at its start) and taken again at dt x target / dS. A step below
  min_step_s stops the run. Each of their steps ends at rest: a
  quasi-static stage runs its duration.
*/
class FlowStepRule
{
  public:
    static constexpr bool ends_at_rest = true;
    static constexpr const char* automatic_step =
        "automatic: the last step x solver.seepage_saturation_change / its "
        "largest saturation change, at most twice the last";
    static constexpr const char* fixed_step = "fixed dt_s";
    //! The shortest step the flow may ask for before the run stops, s.
    static constexpr double min_step_s = 1.0e-6;
    //! A step whose saturation change exceeds this many times
    //! solver.seepage_saturation_change is taken again, shorter.
    static constexpr double retake_factor = 2.0;

    explicit FlowStepRule( const SolverConfig& solver )
        : _next_dt( solver.seepage_initial_dt_s )
    {
    }

    //! A stage starts: its conditions may change the flow at once, so the
    //! steps start again from solver.seepage_initial_dt_s.
    void startStage( const SolverConfig& solver )
    {
        _next_dt = solver.seepage_initial_dt_s;
    }

    //! True if the last advance gave its step back without taking it: the
    //! caller takes it again at nextStep.
    bool stepGivenBack() const { return _given_back; }

    //! The steps given back so far.
    long stepsRetaken() const { return _retaken; }

    //! The next step: solver.dt_s if fixed, else the flow's.
    template <class State>
    double nextStep( const State& s, const WaveSpeedLimit& ) const
    {
        return s.solver.dt_s > 0.0 ? s.solver.dt_s : _next_dt;
    }

    //! Takes up the flow's steps again after other steps, the last of
    //! `dt`: the next is twice that (the auto scheme's return to
    //! quasi-static steps).
    void resumeAfter( const double dt ) { _next_dt = 2.0 * dt; }

  protected:
    /*!
      \brief True if a step dt that changed a free point's saturation by
      `change` is given back (a fixed solver.dt_s never is): the change
      exceeds retake_factor x solver.seepage_saturation_change. The next
      step is then dt x solver.seepage_saturation_change / change (the
      `scheme`'s step names it if that is below min_step_s); the scheme
      restores the state at the step's start.
    */
    bool givesBack( const SolverConfig& solver, const double dt,
                    const double change, const char* scheme )
    {
        _given_back = solver.dt_s <= 0.0 &&
                      change > retake_factor * solver.seepage_saturation_change;
        if ( !_given_back )
            return false;
        ++_retaken;
        _next_dt = dt * solver.seepage_saturation_change / change;
        stopIfTooShort( solver, dt, change, scheme );
        return true;
    }

    //! The next step after a step dt that changed a free point's saturation
    //! by `change` at most (the `scheme`'s step names it if it stops).
    void chooseNextStep( const SolverConfig& solver, const double dt,
                         const double change, const char* scheme )
    {
        const double allowed =
            change > 0.0 ? dt * solver.seepage_saturation_change / change
                         : 2.0 * _next_dt;
        _next_dt = std::min( allowed, 2.0 * std::max( dt, _next_dt ) );
        stopIfTooShort( solver, dt, change, scheme );
    }

  private:
    //! Stops the run if the next step is below min_step_s.
    void stopIfTooShort( const SolverConfig& solver, const double dt,
                         const double change, const char* scheme ) const
    {
        if ( solver.dt_s > 0.0 || _next_dt >= min_step_s )
            return;
        std::ostringstream what;
        what << "the " << scheme << " step fell to " << _next_dt << " s, below "
             << min_step_s << " s: a step of " << dt
             << " s changed a point's saturation by " << change
             << " (solver.seepage_saturation_change = "
             << solver.seepage_saturation_change << ")";
        throw SimulationError( what.str() );
    }

    double _next_dt;          //!< s
    bool _given_back = false; //!< the last step was given back
    long _retaken = 0;        //!< steps given back so far
};

} // namespace mpm

#endif // MPM_FLOW_STEP_RULE_HPP
