#ifndef MPM_HELD_SKELETON_FLOW_HPP
#define MPM_HELD_SKELETON_FLOW_HPP

#include <mpm_pore_pressure.hpp>
#include <mpm_seepage.hpp>
#include <mpm_timestep.hpp>
#include <physics/mpm_kinematics.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_cell_pressure_phase.hpp>
#include <solver/steps/mpm_held_solid.hpp>
#include <solver/steps/mpm_pressure_projection.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! What a flow step through the held skeleton did (HeldSkeletonFlow).
struct FlowReport
{
    PointUpdateReport report; //!< its point loop
    //! The largest change of a free point's saturation, before the cell
    //! equilibrium (which only redistributes a cell's water among its
    //! points, whatever the step).
    double saturation_change = 0.0;
};

//---------------------------------------------------------------------------//
/*!
  \brief One step of the water's flow in real time through the skeleton
  held at every node (docs/formulation.md §10), the seepage and
  quasi-static schemes' flow: the semi-implicit step with the solid fixed.
  The predictor's water velocities are Darcy's (the drag solve with the
  water's inertia m_w / dt negligible at steps of seconds to hours), each
  cell's pressure increment of Eq. 8 at the new time is solved with the
  unsaturated storage exact (Newton), and the points take it with the
  scheme's increment rule; nothing moves.
*/
template <class ExecSpace>
class HeldSkeletonFlow
{
  public:
    HeldSkeletonFlow() = default;
    explicit HeldSkeletonFlow( const SimulationState<ExecSpace>& state )
        : _phases( state, true )
        , _projection( state.grid.geometry )
        , _held_i( "held_skeleton_flags_i", state.grid.geometry.nx + 1,
                   state.grid.geometry.ny + 1 )
        , _S_before_p( "held_skeleton_S_before_p", state.particles.size() )
    {
    }

    TwoPhaseStepPhases<ExecSpace>& phases() { return _phases; }
    PressureProjection<ExecSpace>& projection() { return _projection; }
    const PressureProjection<ExecSpace>& projection() const
    {
        return _projection;
    }

    //! The flow over dt, each point taking its cell's increment with the
    //! rule `increment` (CellPressureIncrement, FixedStressCellIncrement);
    //! `limit` is the skeleton's CFL limit (the FLIP/PIC reference).
    template <class Increment>
    FlowReport advance( SimulationState<ExecSpace>& s, const double dt,
                        const StepSettings& settings,
                        const WaveSpeedLimit& limit,
                        const Increment& increment )
    {
        const ExecSpace exec;
        // The solid fixed at every node for the step.
        const HeldSolid<ExecSpace> held( exec, s.grid.flags_i, _held_i );
        Kokkos::deep_copy( exec, _S_before_p, s.water_particles.S_p );
        // 1. P2G at p_w of the step's start; 1b. the base cells' share.
        _phases.scatter( exec, s, settings );
        // 2. The predictor: the water's Darcy velocities (the solid held).
        _phases.updateGrid( exec, s, dt, settings );
        // 2b. Each cell's pressure increment of Eq. 8 at the new time and
        // the water velocities it corrects.
        const auto pore_pressure =
            solveCellPressures( exec, s, dt, _phases, _projection, increment );
        // 3. G2P; 4. the remap (the solid at rest, the water's seepage).
        _phases.gatherAndRemap(
            exec, s, dt,
            physics::stepFlipFraction( s.solver.flip_fraction, dt,
                                       limit.dt_limit ) );
        // 5. With B-bar: the cell averages of the velocity gradients.
        if ( s.solver.bbar )
            _bbar( exec, s );
        // 5-9 in one point loop: each point's pressure increment from its
        // cell's, the retention state (no strain: the positions, porosity
        // and stress stay).
        const DryWaveSpeed<ExecSpace> skeleton_wave( s.particles );
        FlowReport flow;
        flow.report =
            _phases.updatePoints( exec, s, dt, pore_pressure, skeleton_wave );
        flow.saturation_change = maxSaturationChange(
            exec, s.particles, s.water_particles, _S_before_p );
        // 6b. Cell water equilibrium.
        if ( s.solver.cell_equilibrium )
            _phases.cellEquilibrium( exec, s, flow.report, skeleton_wave,
                                     [&]()
                                     {
                                         return criticalTimeStep(
                                             exec, s.particles, s.materials,
                                             s.grid.geometry.h );
                                     } );
        s.retention_current = s.analysis != AnalysisType::Saturated;
        return flow;
    }

  private:
    TwoPhaseStepPhases<ExecSpace> _phases;
    PressureProjection<ExecSpace> _projection;
    BbarCellAverages<ExecSpace> _bbar;
    typename HeldSolid<ExecSpace>::flag_view _held_i;
    Kokkos::View<double*, DeviceType<ExecSpace>> _S_before_p;
};

} // namespace mpm

#endif // MPM_HELD_SKELETON_FLOW_HPP
