#ifndef MPM_DRY_STEP_HPP
#define MPM_DRY_STEP_HPP

#include <mpm_timestep.hpp>
#include <physics/mpm_kinematics.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_cfl_step.hpp>
#include <solver/steps/mpm_dry_step_phases.hpp>
#include <solver/steps/mpm_pressure_solve_stats.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The explicit MUSL step of a dry (single-phase) scene
  (docs/formulation.md §4): the two-phase step's phases on the solid alone,
  at the CFL limit of the skeleton's P wave.
*/
template <class ExecSpace>
class DryStep : public CflStepRule
{
  public:
    static constexpr const char* scheme = "explicit";
    static constexpr const char* limiting_wave = "P wave of the skeleton";

    explicit DryStep( const SimulationState<ExecSpace>& state )
        : _phases( state.grid.geometry )
    {
    }

    //! The CFL limit of the skeleton's P wave (StepScheme).
    WaveSpeedLimit cflLimit( const SimulationState<ExecSpace>& s ) const
    {
        return criticalTimeStep( ExecSpace(), s.particles, s.materials,
                                 s.grid.geometry.h );
    }

    //! One step (StepScheme), the FLIP/PIC blend referred to `limit`.
    PointUpdateReport advance( SimulationState<ExecSpace>& s, const double dt,
                               const StepSettings& settings,
                               const WaveSpeedLimit& limit )
    {
        const ExecSpace exec;
        // 1. P2G: mass, momentum and force (gravity, loads, stress).
        _phases.scatter( exec, s.particles, s.grid.geometry, settings.gravity_x,
                         settings.gravity_y, s.conditions.load_force );
        // 2. Nodal velocities.
        _phases.updateGrid( exec, s.grid, dt, settings.damping,
                            s.solver.inertia_scaling );
        // 3. G2P: point velocities (FLIP/PIC) and displacement increments;
        // 4. the MUSL remap.
        _phases.gatherAndRemap(
            exec, s.particles, s.grid, dt,
            physics::stepFlipFraction( s.solver.flip_fraction, dt,
                                       limit.dt_limit ) );
        // 5. With B-bar: the cell averages of the velocity gradients.
        if ( s.solver.bbar )
            _bbar( exec, s );
        // 6-9 in one point loop: the gradient, the stress, the positions
        // and the diagnostics of the new state (10: the next CFL limit).
        return _phases.updatePoints( exec, s.particles, s.grid, s.materials, dt,
                                     s.solver.bbar,
                                     s.solver.remove_points_leaving_grid );
    }

    //! The dry step solves no pressure equation.
    const PressureSolveStats* pressureSolveStats() const { return nullptr; }

  private:
    DryStepPhases<ExecSpace> _phases;
    BbarCellAverages<ExecSpace> _bbar;
};

} // namespace mpm

#endif // MPM_DRY_STEP_HPP
