#ifndef MPM_SEEPAGE_STEP_HPP
#define MPM_SEEPAGE_STEP_HPP

#include <mpm_pore_pressure_increments.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_flow_step_rule.hpp>
#include <solver/steps/mpm_held_skeleton_flow.hpp>
#include <solver/steps/mpm_point_state_copy.hpp>
#include <solver/steps/mpm_skeleton_relaxation.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The seepage step (docs/formulation.md §10): the water flows in real
  time through a skeleton held at every node, the transient seepage of a
  rigid soil (HeldSkeletonFlow, each point taking its cell's increment);
  nothing moves, so no wave limits the step. The step is set by the flow
  (FlowStepRule): its largest change of a free point's saturation, taken
  before the cell equilibrium; a step that changed it by more than twice
  the target is given back and taken again, shorter. Backward Euler's
  error in time scales with it.
*/
template <class ExecSpace>
class SeepageStep : public FlowStepRule
{
  public:
    static constexpr const char* scheme = "seepage";
    static constexpr const char* limiting_wave =
        "none (the skeleton is held; the step is set by the flow's "
        "saturation change, solver.seepage_saturation_change)";

    explicit SeepageStep( const SimulationState<ExecSpace>& state )
        : FlowStepRule( state.solver )
        , _flow( state )
        , _step_start( state )
    {
    }

    //! The CFL limit of the skeleton's P wave (StepScheme; reported only:
    //! the held skeleton does not move).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStep( ExecSpace(), s.particles, s.materials,
                                 s.grid.geometry.h );
    }

    //! One step (StepScheme) of the flow through the held skeleton, or
    //! none if the step is given back (stepGivenBack).
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        // 1-9. The flow over dt, each point taking its cell's increment.
        _step_start.save( s );
        const FlowReport flow = _flow.advance(
            s, dt, settings, limit,
            CellPressureIncrement<ExecSpace>{
                s.water_grid.dp_w_c, s.particles.x_p, s.grid.geometry } );
        // 10. A step that changed a saturation too much is taken again,
        // shorter; else the next step from its saturation change.
        if ( givesBack( s.solver, dt, flow.saturation_change, scheme ) )
        {
            _step_start.restore( s );
            return PointUpdateReport();
        }
        chooseNextStep( s.solver, dt, flow.saturation_change, scheme );
        return flow.report;
    }

    //! The pressure solves so far.
    const PressureSolveStats* pressureSolveStats() const
    {
        return &_flow.projection().stats();
    }

    //! The seepage step keeps no water in transit and relaxes nothing.
    double waterInTransit() const { return 0.0; }
    const RelaxationStats* relaxationStats() const { return nullptr; }

  private:
    HeldSkeletonFlow<ExecSpace> _flow;
    PointStateCopy<ExecSpace> _step_start;
};

} // namespace mpm

#endif // MPM_SEEPAGE_STEP_HPP
