#ifndef MPM_SKELETON_RELAXATION_HPP
#define MPM_SKELETON_RELAXATION_HPP

#include <mpm_device_type.hpp>
#include <mpm_pore_pressure_increments.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_bbar_cell_averages.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>

namespace mpm
{
//! What one relaxation did (SkeletonRelaxation::relax).
struct RelaxationReport
{
    PointUpdateReport last; //!< the last step's point loop
    long steps = 0;         //!< damped steps taken
    bool at_rest = false;   //!< the fastest point fell below the rest speed
    double max_speed = 0.0; //!< of the last step, m/s
};

//! What the relaxations of a run did (metrics.json's `relaxation`).
struct RelaxationStats
{
    long relaxations = 0; //!< one per quasi-static step
    long steps = 0;       //!< damped steps, in all
    long max_steps = 0;   //!< the most one relaxation took

    void add( const RelaxationReport& relaxed )
    {
        ++relaxations;
        steps += relaxed.steps;
        max_steps = std::max( max_steps, relaxed.steps );
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The quasi-static scheme's relaxation of the skeleton
  (docs/formulation.md §11): the skeleton moves to equilibrium under the
  points' pore pressures, each held (HeldPorePressure), by damped two-phase
  steps (the stage's local damping, at least solver.relaxation_damping) at
  the Courant number times the skeleton's CFL limit, from rest, until the
  fastest point moves slower than solver.relaxation_speed_m_per_s, at
  most solver.relaxation_max_steps. The steps are pseudo-time: the
  simulated time and the step count stay. The water is held to the solid
  (WaterOnGrid::held_to_solid: the flow is the step's own) and afterwards
  given back the seepage velocities the flow left, the next flow's start.
  The points are left at rest.
*/
template <class ExecSpace>
class SkeletonRelaxation
{
  public:
    SkeletonRelaxation() = default;

    //! Relaxes `s`'s skeleton with `phases`' sums (its cell lists unused).
    RelaxationReport relax( const ExecSpace& exec,
                            SimulationState<ExecSpace>& s,
                            TwoPhaseStepPhases<ExecSpace>& phases,
                            const StepSettings& settings )
    {
        StepSettings damped = settings;
        damped.damping =
            std::max( settings.damping, s.solver.relaxation_damping );
        const double rest_speed = s.solver.relaxation_speed_m_per_s;
        Kokkos::deep_copy( exec, s.particles.v_p, 0.0 );
        keepSeepageVelocities( exec, s );
        const auto held =
            TwoPhaseStepPhases<ExecSpace>::WaterOnGrid::held_to_solid;
        RelaxationReport report;
        int removed = 0;
        while ( report.steps < s.solver.relaxation_max_steps )
        {
            const WaveSpeedLimit limit = criticalTimeStep(
                exec, s.particles, s.materials, s.grid.geometry.h );
            const double dt = s.solver.courant_number * limit.dt_limit;
            // 1. P2G at the held p_w; 2. both phases' nodal velocities,
            // damped.
            phases.scatter( exec, s, damped );
            phases.updateGrid( exec, s, dt, damped, held );
            // 3. G2P; 4. the remap.
            phases.gatherAndRemap( exec, s, dt, s.solver.flip_fraction, held );
            // 5. With B-bar: the cell averages of the velocity gradients.
            if ( s.solver.bbar )
                _bbar( exec, s );
            // 5-9: the strain, porosity and effective stress of the moving
            // skeleton, each point's p_w held.
            const DryWaveSpeed<ExecSpace> skeleton_wave( s.particles );
            report.last = phases.updatePoints(
                exec, s, dt,
                TwoPhaseStepPhases<ExecSpace>::porePressure(
                    s, dt, HeldPorePressure{} ),
                skeleton_wave );
            ++report.steps;
            removed += report.last.num_removed;
            report.max_speed = std::sqrt( report.last.diagnostics.max_speed2 );
            if ( report.last.first_outside >= 0 ||
                 !( report.max_speed >= rest_speed ) )
                break;
        }
        report.at_rest = report.max_speed < rest_speed;
        report.last.num_removed = removed;
        // The step ends at rest, its CFL limit the skeleton's; the water
        // seeps on as the flow left it.
        Kokkos::deep_copy( exec, s.particles.v_p, 0.0 );
        if ( s.water_particles.allocated() )
            Kokkos::deep_copy( exec, s.water_particles.v_w_p, _v_w_p );
        const WaveSpeedLimit after = criticalTimeStep(
            exec, s.particles, s.materials, s.grid.geometry.h );
        StepDiagnostics& diagnostics = report.last.diagnostics;
        diagnostics.kinetic_energy = 0.0;
        diagnostics.max_speed2 = 0.0;
        diagnostics.dt_limit = after.dt_limit;
        diagnostics.max_wave_speed = after.max_wave_speed;
        return report;
    }

  private:
    //! Keeps the points' water velocities (the flow's, the solid at rest).
    void keepSeepageVelocities( const ExecSpace& exec,
                                const SimulationState<ExecSpace>& s )
    {
        if ( !s.water_particles.allocated() )
            return;
        if ( _v_w_p.extent( 0 ) != s.water_particles.v_w_p.extent( 0 ) )
            _v_w_p = Kokkos::View<double* [2], DeviceType<ExecSpace>>(
                "relaxation_v_w_p", s.water_particles.v_w_p.extent( 0 ) );
        Kokkos::deep_copy( exec, _v_w_p, s.water_particles.v_w_p );
    }

    BbarCellAverages<ExecSpace> _bbar;
    Kokkos::View<double* [2], DeviceType<ExecSpace>> _v_w_p;
};

} // namespace mpm

#endif // MPM_SKELETON_RELAXATION_HPP
