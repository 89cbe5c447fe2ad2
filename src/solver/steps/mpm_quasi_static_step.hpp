#ifndef MPM_QUASI_STATIC_STEP_HPP
#define MPM_QUASI_STATIC_STEP_HPP

#include <mpm_fixed_stress.hpp>
#include <mpm_pore_pressure_increments.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_flow_step_rule.hpp>
#include <solver/steps/mpm_held_skeleton_flow.hpp>
#include <solver/steps/mpm_point_state_copy.hpp>
#include <solver/steps/mpm_skeleton_relaxation.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <sstream>

namespace mpm
{
//! One quasi-static step tried (QuasiStaticStep::attempt).
struct QuasiStaticAttempt
{
    PointUpdateReport report; //!< the step's (the relaxation's last loop)
    RelaxationReport relaxed; //!< what the relaxation did
    bool at_rest = false;     //!< the skeleton found its equilibrium
    //! The flow changed a saturation too much: the state is the step's
    //! start again, nothing relaxed (FlowStepRule::stepGivenBack).
    bool given_back = false;
};

//---------------------------------------------------------------------------//
/*!
  \brief The quasi-static coupled step (docs/formulation.md §11): real
  time, no inertia, the skeleton in equilibrium at the end of every step,
  by the fixed-stress split. A. The water flows over dt through the
  skeleton at rest (HeldSkeletonFlow) with each point's storage raised by
  the skeleton's, S^2 / E_c (the pore volume the skeleton will give a
  pascal of p_w at a fixed total stress), the last step's water in transit
  a source. B. The skeleton relaxes to equilibrium under the new pore
  pressures, each held (SkeletonRelaxation); none found means the soil
  has failed and the run stops. C. What the flow gave the skeleton less
  what its pore volume took up is the water in transit, stored by the next
  step's flow: no water is lost, and the stored water plus the water in
  transit balance the seepage, rain and runoff. The step is set by the flow
  (FlowStepRule); no wave limits it. A flow that changed a saturation by
  more than twice the target gives the step back before B: the state is
  restored and the step taken again, shorter.
*/
template <class ExecSpace>
class QuasiStaticStep : public FlowStepRule
{
  public:
    static constexpr const char* scheme = "quasi_static";
    static constexpr const char* limiting_wave =
        "none (the skeleton relaxes to equilibrium in each step; the step is "
        "set by the flow's saturation change, "
        "solver.seepage_saturation_change)";

    explicit QuasiStaticStep( const SimulationState<ExecSpace>& state )
        : FlowStepRule( state.solver )
        , _flow( state )
        , _skeleton_storage_p( "skeleton_storage_p", state.particles.size() )
        , _anticipated_p( "anticipated_water_p", state.particles.size() )
        , _stored_p( "stored_water_p", state.particles.size() )
        , _transit_p( "water_in_transit_p", state.particles.size() )
        , _step_start( state )
    {
        _flow.projection().setSkeletonStorage( _skeleton_storage_p );
    }

    //! The CFL limit of the skeleton's P wave (StepScheme; the
    //! relaxation's steps take it).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStep( ExecSpace(), s.particles, s.materials,
                                 s.grid.geometry.h );
    }

    //! One step (StepScheme): the flow, the relaxation, the water in
    //! transit. Throws SimulationError if the skeleton finds no
    //! equilibrium.
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        const QuasiStaticAttempt step = attempt( s, dt, settings, limit );
        if ( !step.given_back && !step.at_rest &&
             step.report.first_outside < 0 )
            throw SimulationError( noEquilibrium( s, step.relaxed ) );
        return step.report;
    }

    /*!
      \brief One step, as advance, that does not throw when the skeleton
      finds no equilibrium: it then returns at_rest false with the state as
      the relaxation left it (the auto scheme goes back to the step's start,
      restoreStepStart, and follows the failure dynamically).
    */
    QuasiStaticAttempt attempt( SimulationState<ExecSpace>& s, const double dt,
                                const StepSettings& settings,
                                const WaveSpeedLimit& limit )
    {
        const ExecSpace exec;
        // A. The flow over dt through the skeleton at rest, each point's
        // storage with the skeleton's, the water in transit a source; a
        // flow that changed a saturation too much is given back.
        _step_start.save( s );
        skeletonStorages( exec, s.particles, s.water_particles, s.materials,
                          _skeleton_storage_p );
        Kokkos::deep_copy( exec, _anticipated_p, 0.0 );
        const FlowReport flow = _flow.advance(
            s, dt, settings, limit,
            FixedStressCellIncrement<ExecSpace>{
                { s.water_grid.dp_w_c, s.particles.x_p, s.grid.geometry },
                _skeleton_storage_p,
                _transit_p,
                _anticipated_p,
                s.particles.vol_p } );
        QuasiStaticAttempt step;
        if ( givesBack( s.solver, dt, flow.saturation_change, scheme ) )
        {
            _step_start.restore( s );
            step.given_back = true;
            return step;
        }
        // B. The skeleton relaxed to equilibrium under the new pore
        // pressures, each held.
        pointWaterVolumes( exec, s.particles, s.water_particles, s.water,
                           _stored_p );
        step.relaxed = _relaxation.relax( exec, s, _flow.phases(), settings );
        _relaxations.add( step.relaxed );
        step.at_rest = step.relaxed.at_rest;
        step.report = step.relaxed.last;
        if ( !step.at_rest || step.report.first_outside >= 0 )
            return step;
        // C. The water in transit: what the flow gave the skeleton less
        // what its pore volume took up (a prescribed p_w's condition gave
        // what its point took up).
        const RelaxationWater left =
            pointWaterInTransit( exec, s.particles, s.water_particles, s.water,
                                 _anticipated_p, _stored_p, _transit_p );
        _transit = left.in_transit;
        // D. The next step from the flow's saturation change.
        chooseNextStep( s.solver, dt, flow.saturation_change, scheme );
        step.report.water = flow.report.water;
        step.report.water.prescribed += left.prescribed;
        step.report.num_removed += flow.report.num_removed;
        return step;
    }

    //! Gives `s` back the state at the start of the last attempt.
    void restoreStepStart( SimulationState<ExecSpace>& s ) const
    {
        _step_start.restore( s );
    }

    //! The pressure solves so far.
    const PressureSolveStats* pressureSolveStats() const
    {
        return &_flow.projection().stats();
    }

    //! The water in transit after the last step, m^3 per metre.
    double waterInTransit() const { return _transit; }

    //! The relaxations so far.
    const RelaxationStats* relaxationStats() const { return &_relaxations; }

  private:
    //! Why the run stops when the skeleton found no equilibrium.
    static std::string noEquilibrium( const SimulationState<ExecSpace>& s,
                                      const RelaxationReport& relaxed )
    {
        std::ostringstream what;
        what << "the skeleton found no equilibrium at t = " << s.time
             << " s: after " << relaxed.steps
             << " relaxation steps (solver.relaxation_max_steps) its fastest "
                "point still moves at "
             << relaxed.max_speed << " m/s (solver.relaxation_speed_m_per_s = "
             << s.solver.relaxation_speed_m_per_s
             << "): the soil is failing; the semi_implicit scheme follows a "
                "failure";
        return what.str();
    }

    HeldSkeletonFlow<ExecSpace> _flow;
    SkeletonRelaxation<ExecSpace> _relaxation;
    Kokkos::View<double*, DeviceType<ExecSpace>> _skeleton_storage_p,
        _anticipated_p, _stored_p, _transit_p;
    PointStateCopy<ExecSpace> _step_start;
    double _transit = 0.0; //!< m^3 per metre
    RelaxationStats _relaxations;
};

} // namespace mpm

#endif // MPM_QUASI_STATIC_STEP_HPP
