#ifndef MPM_STEP_SCHEME_HPP
#define MPM_STEP_SCHEME_HPP

#include <case/mpm_case_config.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_auto_step.hpp>
#include <solver/steps/mpm_dry_step.hpp>
#include <solver/steps/mpm_explicit_two_phase_step.hpp>
#include <solver/steps/mpm_quasi_static_step.hpp>
#include <solver/steps/mpm_seepage_step.hpp>
#include <solver/steps/mpm_semi_implicit_step.hpp>

#include <variant>

namespace mpm
{
/*!
  \brief The step schemes a simulation can run, one type each. Every one
  offers:
  - `advance(state, dt, settings, limit)`: one step of size dt, its phases
    in order; `limit` is the (inertia-scaled) CFL limit of the state at the
    step's start, which the explicit schemes take as the FLIP/PIC blend's
    reference (physics::stepFlipFraction); returns the point loop's report;
  - `nextStep(state, limit)`: the step it takes next, given the CFL limit
    `limit` of the state now;
  - `stepGivenBack()`: true if the last advance took no step, the state
    as before it: the caller takes the step again at nextStep (the flow
    changed a saturation too much, or the auto scheme handed off);
    `stepsRetaken()` counts them;
  - `startStage(solver)`: a stage starts (the flow's steps start again
    from solver.seepage_initial_dt_s);
  - `cflLimit(state)`: the CFL limit (Courant number 1) and largest wave
    speed of its fastest wave on the points now, of the real (not
    inertia-scaled) system;
  - `pressureSolveStats()`: its pressure solves, or null;
  - `relaxationStats()`: its relaxations of the skeleton, or null;
  - `waterInTransit()`: the water it has taken in and not yet given to the
    points, m^3 per metre (QuasiStaticStep);
  - `ends_at_rest`: true if each step ends at rest (a quasi-static stage
    then has nothing to settle and runs its duration; AutoStep's changes
    with the scheme it runs);
  - `scheme`, `automatic_step`, `fixed_step` and `limiting_wave`: its name
    as the case file writes it, how it chooses its step (without and with
    solver.dt_s) and the wave that limits its step.
*/
template <class ExecSpace>
using StepScheme =
    std::variant<DryStep<ExecSpace>, ExplicitTwoPhaseStep<ExecSpace>,
                 SemiImplicitStep<ExecSpace>, SeepageStep<ExecSpace>,
                 QuasiStaticStep<ExecSpace>, AutoStep<ExecSpace>>;

//! The scheme of `state`'s scene and [solver] scheme: the dry step for a
//! dry scene, else the explicit, semi-implicit, seepage, quasi-static or
//! auto two-phase step.
template <class ExecSpace>
StepScheme<ExecSpace> makeStepScheme( const SimulationState<ExecSpace>& state )
{
    if ( !state.twoPhase() )
        return StepScheme<ExecSpace>( std::in_place_type<DryStep<ExecSpace>>,
                                      state );
    if ( state.solver.scheme == TwoPhaseScheme::SemiImplicit )
        return StepScheme<ExecSpace>(
            std::in_place_type<SemiImplicitStep<ExecSpace>>, state );
    if ( state.solver.scheme == TwoPhaseScheme::Seepage )
        return StepScheme<ExecSpace>(
            std::in_place_type<SeepageStep<ExecSpace>>, state );
    if ( state.solver.scheme == TwoPhaseScheme::QuasiStatic )
        return StepScheme<ExecSpace>(
            std::in_place_type<QuasiStaticStep<ExecSpace>>, state );
    if ( state.solver.scheme == TwoPhaseScheme::Auto )
        return StepScheme<ExecSpace>( std::in_place_type<AutoStep<ExecSpace>>,
                                      state );
    return StepScheme<ExecSpace>(
        std::in_place_type<ExplicitTwoPhaseStep<ExecSpace>>, state );
}

} // namespace mpm

#endif // MPM_STEP_SCHEME_HPP
