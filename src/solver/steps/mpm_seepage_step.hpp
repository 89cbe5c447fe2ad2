#ifndef MPM_SEEPAGE_STEP_HPP
#define MPM_SEEPAGE_STEP_HPP

#include <mpm_pore_pressure.hpp>
#include <mpm_seepage.hpp>
#include <mpm_timestep.hpp>
#include <physics/mpm_kinematics.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_cell_pressure_phase.hpp>
#include <solver/steps/mpm_pressure_projection.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <sstream>
#include <utility>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The seepage step (docs/formulation.md §10): the water flows in real
  time through a skeleton held at every node, the transient seepage of a
  rigid soil. It is the semi-implicit step with the solid fixed: the
  predictor's water velocities are Darcy's (the drag solve with the water's
  inertia m_w / dt negligible at steps of seconds to hours), each cell's
  pressure increment of Eq. 8 at the new time is solved with the
  unsaturated storage exact (Newton), and the points take it; nothing
  moves, so no wave limits the step. The step is set by the flow: after a
  step in which the largest change of a point's saturation was dS, the
  next is dt solver.seepage_saturation_change / dS, at most twice the last
  one (solver.seepage_initial_dt_s first; a fixed solver.dt_s if given);
  dS is the flow's, taken before the cell equilibrium, which redistributes a
  cell's water among its points whatever the step, and over the points
  whose p_w is free. Backward Euler's error in time scales with it.
*/
template <class ExecSpace>
class SeepageStep
{
  public:
    static constexpr const char* scheme = "seepage";
    static constexpr const char* automatic_step =
        "automatic: the last step x solver.seepage_saturation_change / its "
        "largest saturation change, at most twice the last";
    static constexpr const char* fixed_step = "fixed dt_s";
    //! The skeleton stays where it is (a quasi-static stage has nothing to
    //! settle).
    static constexpr bool moves_skeleton = false;
    //! The shortest step the flow may ask for before the run stops, s.
    static constexpr double min_step_s = 1.0e-6;
    static constexpr const char* limiting_wave =
        "none (the skeleton is held; the step is set by the flow's "
        "saturation change, solver.seepage_saturation_change)";

    explicit SeepageStep( const SimulationState<ExecSpace>& state )
        : _phases( state, true )
        , _projection( state.grid.geometry )
        , _held_i( "seepage_held_flags_i", state.grid.geometry.nx + 1,
                   state.grid.geometry.ny + 1 )
        , _S_before_p( "seepage_S_before_p", state.particles.size() )
        , _next_dt( state.solver.seepage_initial_dt_s )
    {
    }

    //! The CFL limit of the skeleton's P wave (StepScheme; reported only:
    //! the held skeleton does not move).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStep( ExecSpace(), s.particles, s.materials,
                                 s.grid.geometry.h );
    }

    //! The next step: solver.dt_s if fixed, else the flow's.
    double nextStep( const SimulationState<ExecSpace>& s,
                     const WaveSpeedLimit& ) const
    {
        return s.solver.dt_s > 0.0 ? s.solver.dt_s : _next_dt;
    }

    //! One step (StepScheme) of the flow through the held skeleton.
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        const ExecSpace exec;
        // The solid fixed at every node for the step (the stage's flags
        // back at its end, also if the pressure solve stops the run).
        holdSolidFlags( exec, s.grid.flags_i, _held_i );
        const HeldSolid held( s.grid.flags_i, _held_i );
        Kokkos::deep_copy( exec, _S_before_p, s.water_particles.S_p );
        // 1. P2G at p_w of the step's start; 1b. the base cells' share.
        _phases.scatter( exec, s, settings );
        // 2. The predictor: the water's Darcy velocities (the solid held).
        _phases.updateGrid( exec, s, dt, settings );
        // 2b. Each cell's pressure increment of Eq. 8 at the new time and
        // the water velocities it corrects.
        const auto pore_pressure =
            solveCellPressures( exec, s, dt, _phases, _projection );
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
        PointUpdateReport report =
            _phases.updatePoints( exec, s, dt, pore_pressure, skeleton_wave );
        // The largest change the flow made to a free point's saturation,
        // before the cell equilibrium (which only redistributes a cell's
        // water among its points, whatever the step).
        const double change = maxSaturationChange(
            exec, s.particles, s.water_particles, _S_before_p );
        // 6b. Cell water equilibrium.
        if ( s.solver.cell_equilibrium )
            _phases.cellEquilibrium( exec, s, report, skeleton_wave,
                                     [&]() { return cflLimit( s ); } );
        s.retention_current = s.analysis != AnalysisType::Saturated;
        // 10. The next step from that change.
        chooseNextStep( s.solver, dt, change );
        return report;
    }

    //! The pressure solves so far.
    const PressureSolveStats* pressureSolveStats() const
    {
        return &_projection.stats();
    }

  private:
    using flag_view = typename GridViews<ExecSpace>::int_view;

    //! The next step after a step dt that changed a free point's saturation
    //! by `change` at most: dt seepage_saturation_change / change, at most
    //! twice the last; a step below min_step_s stops the run.
    void chooseNextStep( const SolverConfig& solver, const double dt,
                         const double change )
    {
        const double allowed =
            change > 0.0 ? dt * solver.seepage_saturation_change / change
                         : 2.0 * _next_dt;
        _next_dt = std::min( allowed, 2.0 * std::max( dt, _next_dt ) );
        if ( solver.dt_s > 0.0 || _next_dt >= min_step_s )
            return;
        std::ostringstream what;
        what << "the seepage step fell to " << _next_dt << " s, below "
             << min_step_s << " s: a step of " << dt
             << " s changed a point's saturation by " << change
             << " (solver.seepage_saturation_change = "
             << solver.seepage_saturation_change << ")";
        throw SimulationError( what.str() );
    }

    //! Swaps the held flags into the grid for its lifetime.
    class HeldSolid
    {
      public:
        HeldSolid( flag_view& flags, flag_view& held )
            : _flags( flags )
            , _held( held )
        {
            std::swap( _flags, _held );
        }
        ~HeldSolid() { std::swap( _flags, _held ); }
        HeldSolid( const HeldSolid& ) = delete;
        HeldSolid& operator=( const HeldSolid& ) = delete;

      private:
        flag_view& _flags;
        flag_view& _held;
    };

    TwoPhaseStepPhases<ExecSpace> _phases;
    PressureProjection<ExecSpace> _projection;
    BbarCellAverages<ExecSpace> _bbar;
    flag_view _held_i;
    Kokkos::View<double*, DeviceType<ExecSpace>> _S_before_p;
    double _next_dt; //!< s
};

} // namespace mpm

#endif // MPM_SEEPAGE_STEP_HPP
