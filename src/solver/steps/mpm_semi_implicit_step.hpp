#ifndef MPM_SEMI_IMPLICIT_STEP_HPP
#define MPM_SEMI_IMPLICIT_STEP_HPP

#include <mpm_pore_pressure.hpp>
#include <mpm_timestep.hpp>
#include <physics/mpm_kinematics.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_cell_pressure_phase.hpp>
#include <solver/steps/mpm_cfl_step.hpp>
#include <solver/steps/mpm_pressure_projection.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

#include <cmath>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The semi-implicit two-phase step (docs/formulation.md §9): the
  explicit step's predictor, then each cell's pressure increment that makes
  the corrected flow satisfy Eq. 8 at the new time (PressureProjection),
  which the points take. The water's stiffness is in the pressure solve, so
  the step is set by the skeleton's P wave, about 20 times the explicit
  step on the paper's slope.
*/
template <class ExecSpace>
class SemiImplicitStep : public CflStepRule
{
  public:
    static constexpr const char* scheme = "semi_implicit";
    static constexpr const char* limiting_wave =
        "P wave of the skeleton (the water's stiffness in the pressure "
        "solve)";

    explicit SemiImplicitStep( const SimulationState<ExecSpace>& state )
        : _phases( state, true )
        , _projection( state.grid.geometry )
    {
    }

    //! The CFL limit of the skeleton's P wave (StepScheme).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStep( ExecSpace(), s.particles, s.materials,
                                 s.grid.geometry.h );
    }

    //! One step (StepScheme); the FLIP/PIC blend's reference is not
    //! `limit`, the skeleton's, but flipReferenceStep.
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& /*limit*/ )
    {
        const ExecSpace exec;
        // 1. P2G: masses, momenta, the mixture force (Eq. 11) and the
        // water force (Eq. 9) at p_w of the step's start; 1b. the base
        // cells' share.
        _phases.scatter( exec, s, settings );
        // 2. The predictor: nodal velocities of both phases, the drag
        // implicit (Eqs. 9-10).
        _phases.updateGrid( exec, s, dt, settings );
        // 2b. Each cell's pressure increment of Eq. 8 at the new time and
        // the nodal velocities it corrects.
        const auto pore_pressure =
            solveCellPressures( exec, s, dt, _phases, _projection );
        // 3. G2P (FLIP/PIC); 4. the MUSL remap of both phases; 4b. the base
        // cells' water.
        _phases.gatherAndRemap(
            exec, s, dt,
            physics::stepFlipFraction( s.solver.flip_fraction, dt,
                                       flipReferenceStep( s ) ) );
        // 5. With B-bar: the cell averages of the velocity gradients.
        if ( s.solver.bbar )
            _bbar( exec, s );
        // 5-9 in one point loop: the gradient, each point's pressure
        // increment from its cell's, the Eq. 2 porosity and the retention
        // state, the effective stress, the positions and the diagnostics of
        // the new state at the skeleton's wave speed.
        const DryWaveSpeed<ExecSpace> skeleton_wave( s.particles );
        PointUpdateReport report =
            _phases.updatePoints( exec, s, dt, pore_pressure, skeleton_wave );
        // 6b. Cell water equilibrium, and the CFL limit after it.
        if ( s.solver.cell_equilibrium )
            _phases.cellEquilibrium( exec, s, report, skeleton_wave,
                                     [&]() { return cflLimit( s ); } );
        // S_p and dS_dp_p now hold the retention law at p_w_p.
        s.retention_current = s.analysis != AnalysisType::Saturated;
        return report;
    }

    //! The pressure solves so far.
    const PressureSolveStats* pressureSolveStats() const
    {
        return &_projection.stats();
    }

  private:
    /*!
      \brief The step at which the FLIP/PIC blend is `flip_fraction`: the
      explicit scheme's CFL limit (Courant number 1, inertia-scaled), so
      the PIC damping per second is the same whichever scheme runs. The
      semi-implicit step is about 20 times longer on the slope; with its own
      (skeleton) limit as reference it damped 20 times less per second, and
      a softened face without tensile strength that the explicit run holds
      slid off in the first seconds of rain (docs/formulation.md §9).
    */
    double flipReferenceStep( const SimulationState<ExecSpace>& s ) const
    {
        const WaveSpeedLimit undrained = criticalTimeStepTwoPhase(
            ExecSpace(), s.particles, s.water_particles, s.materials, s.water,
            s.grid.geometry.h );
        return undrained.dt_limit * std::sqrt( s.solver.inertia_scaling );
    }

    TwoPhaseStepPhases<ExecSpace> _phases;
    PressureProjection<ExecSpace> _projection;
    BbarCellAverages<ExecSpace> _bbar;
};

} // namespace mpm

#endif // MPM_SEMI_IMPLICIT_STEP_HPP
