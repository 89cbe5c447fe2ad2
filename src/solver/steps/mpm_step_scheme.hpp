#ifndef MPM_STEP_SCHEME_HPP
#define MPM_STEP_SCHEME_HPP

#include <io/mpm_case_config.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_dry_step.hpp>
#include <solver/steps/mpm_explicit_two_phase_step.hpp>
#include <solver/steps/mpm_semi_implicit_step.hpp>

#include <variant>

namespace mpm
{
//! The step schemes a simulation can run, one type each; every one offers
//! advance, cflLimit, pressureSolveStats, `scheme` and `limiting_wave`.
template <class ExecSpace>
using StepScheme =
    std::variant<DryStep<ExecSpace>, ExplicitTwoPhaseStep<ExecSpace>,
                 SemiImplicitStep<ExecSpace>>;

//! The scheme of `state`'s scene and [solver] scheme: the dry step for a
//! dry scene, else the explicit or semi-implicit two-phase step.
template <class ExecSpace>
StepScheme<ExecSpace> makeStepScheme( const SimulationState<ExecSpace>& state )
{
    if ( !state.twoPhase() )
        return StepScheme<ExecSpace>( std::in_place_type<DryStep<ExecSpace>>,
                                      state );
    if ( state.solver.scheme == TwoPhaseScheme::SemiImplicit )
        return StepScheme<ExecSpace>(
            std::in_place_type<SemiImplicitStep<ExecSpace>>, state );
    return StepScheme<ExecSpace>(
        std::in_place_type<ExplicitTwoPhaseStep<ExecSpace>>, state );
}

} // namespace mpm

#endif // MPM_STEP_SCHEME_HPP
