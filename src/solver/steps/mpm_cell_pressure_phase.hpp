#ifndef MPM_CELL_PRESSURE_PHASE_HPP
#define MPM_CELL_PRESSURE_PHASE_HPP

#include <mpm_pore_pressure_increments.hpp>
#include <solver/mpm_simulation_state.hpp>
#include <solver/steps/mpm_pressure_projection.hpp>
#include <solver/steps/mpm_two_phase_step_phases.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Step 2b of the schemes with a pressure solve (docs/formulation.md
  §9): each cell's pressure increment of Eq. 8 at the new time and the nodal
  velocities it corrects (PressureProjection::correct, the points' inflow
  and the rule's water in transit as its source). Returns the pore-pressure
  point update that gives each point its cell's increment in the point
  loop with the rule `increment` (CellPressureIncrement, or
  FixedStressCellIncrement).
*/
template <class ExecSpace, class Increment>
auto solveCellPressures( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                         const double dt, TwoPhaseStepPhases<ExecSpace>& phases,
                         PressureProjection<ExecSpace>& projection,
                         const Increment& increment )
{
    const auto pore_pressure =
        TwoPhaseStepPhases<ExecSpace>::porePressure( s, dt, increment );
    const auto source = KOKKOS_LAMBDA( const int q )
    {
        return pore_pressure.inflowSource( q, pore_pressure.inflow_p( q ) ) +
               pore_pressure.increment.transitSource( q, dt );
    };
    projection.correct(
        exec, s.particles, s.water_particles, s.grid, s.water_grid, s.materials,
        s.water, s.analysis == AnalysisType::Saturated,
        s.solver.inertia_scaling, dt, source, s.conditions.inflow_flux_i,
        pressureSolveSettings( s.solver ), phases.cellLists(), s.step + 1,
        s.time );
    return pore_pressure;
}

//! solveCellPressures with each point taking its cell's increment
//! (CellPressureIncrement).
template <class ExecSpace>
auto solveCellPressures( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                         const double dt, TwoPhaseStepPhases<ExecSpace>& phases,
                         PressureProjection<ExecSpace>& projection )
{
    return solveCellPressures(
        exec, s, dt, phases, projection,
        CellPressureIncrement<ExecSpace>{ s.water_grid.dp_w_c, s.particles.x_p,
                                          s.grid.geometry } );
}

} // namespace mpm

#endif // MPM_CELL_PRESSURE_PHASE_HPP
