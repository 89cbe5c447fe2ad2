#ifndef MPM_EXPLICIT_TWO_PHASE_STEP_HPP
#define MPM_EXPLICIT_TWO_PHASE_STEP_HPP

#include <mpm_pore_pressure.hpp>
#include <mpm_timestep.hpp>
#include <physics/mpm_kinematics.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_cfl_step.hpp>
#include <solver/steps/mpm_pressure_solve_stats.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The explicit two-phase MUSL step (the paper's §2.6,
  docs/formulation.md §3): both phases' momentum with the drag implicit,
  the pore pressure from the mass-conservative Eq. 8 at each point, at the
  CFL limit of the undrained mixture or pore-water wave.
*/
template <class ExecSpace>
class ExplicitTwoPhaseStep : public CflStepRule
{
  public:
    static constexpr const char* scheme = "explicit";
    static constexpr const char* limiting_wave =
        "undrained mixture or pore-water wave (saturated fluid stiffness, "
        "drag implicit)";

    explicit ExplicitTwoPhaseStep( const SimulationState<ExecSpace>& state )
        : _phases( state, state.solver.cell_equilibrium )
    {
    }

    //! The CFL limit of the undrained mixture or pore-water wave (StepScheme).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStepTwoPhase( ExecSpace(), s.particles,
                                         s.water_particles, s.materials,
                                         s.water, s.grid.geometry.h );
    }

    //! One step (StepScheme), the FLIP/PIC blend referred to `limit`.
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        const ExecSpace exec;
        // 1. P2G: masses, momenta, the mixture force (Eq. 11) and the
        // water force (Eq. 9); 1b. the base cells' share.
        _phases.scatter( exec, s, settings );
        // 2. Nodal velocities of both phases, the drag implicit (Eqs. 9-10).
        _phases.updateGrid( exec, s, dt, settings );
        // 3. G2P (FLIP/PIC); 4. the MUSL remap of both phases; 4b. the base
        // cells' water.
        _phases.gatherAndRemap(
            exec, s, dt,
            physics::stepFlipFraction( s.solver.flip_fraction, dt,
                                       limit.dt_limit ) );
        // 5. With B-bar: the cell averages of the velocity gradients.
        if ( s.solver.bbar )
            _bbar( exec, s );
        // 5-9 in one point loop: the gradient and water divergence, the
        // pore pressure of Eq. 8 at each point, the Eq. 2 porosity and the
        // retention state, the effective stress, the positions and the
        // diagnostics of the new state.
        const TwoPhaseWaveSpeed<ExecSpace> wave_speed(
            s.particles, s.water_particles, s.water );
        PointUpdateReport report =
            _phases.updatePoints( exec, s, dt,
                                  TwoPhaseStepPhases<ExecSpace>::porePressure(
                                      s, dt, PointWaterBalance{} ),
                                  wave_speed );
        // 6b. Cell water equilibrium, and the CFL limit after it.
        if ( s.solver.cell_equilibrium )
            _phases.cellEquilibrium( exec, s, report, wave_speed,
                                     [&]() { return cflLimit( s ); } );
        // S_p and dS_dp_p now hold the retention law at p_w_p.
        s.retention_current = s.analysis != AnalysisType::Saturated;
        return report;
    }

    //! The explicit step solves no pressure equation.
    const PressureSolveStats* pressureSolveStats() const { return nullptr; }

  private:
    TwoPhaseStepPhases<ExecSpace> _phases;
    BbarCellAverages<ExecSpace> _bbar;
};

} // namespace mpm

#endif // MPM_EXPLICIT_TWO_PHASE_STEP_HPP
