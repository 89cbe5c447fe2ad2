#ifndef MPM_TWO_PHASE_STEP_PHASES_HPP
#define MPM_TWO_PHASE_STEP_PHASES_HPP

#include <mpm_base_cells.hpp>
#include <mpm_cell_equilibrium.hpp>
#include <mpm_cell_point_lists.hpp>
#include <mpm_g2p.hpp>
#include <mpm_grid_update_two_phase.hpp>
#include <mpm_p2g_two_phase.hpp>
#include <mpm_point_update.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_state.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The phases that the explicit and the semi-implicit two-phase steps
  share (docs/formulation.md §3), with the nodal sums and cell point lists
  they keep between steps. Each scheme's advance() runs them in order,
  with its own pore-pressure rule and wave speed.
*/
template <class ExecSpace>
class TwoPhaseStepPhases
{
  public:
    TwoPhaseStepPhases() = default;

    //! The sums of `state`'s grid; the cell point lists if `cell_lists`.
    TwoPhaseStepPhases( const SimulationState<ExecSpace>& state,
                        const bool cell_lists )
        : _node_sums( "p2g_two_phase", state.grid.geometry.numNodes() )
        , _momentum_sums( "remap_two_phase", state.grid.geometry.numNodes() )
    {
        if ( cell_lists )
            _cell_lists = CellPointLists<ExecSpace>(
                state.particles.size(),
                state.grid.geometry.nx * state.grid.geometry.ny );
    }

    //! The points of each cell (cellEquilibrium; the pressure solve).
    CellPointLists<ExecSpace>& cellLists() { return _cell_lists; }

    //! 1. P2G: masses, momenta, the mixture force with Bishop's total
    //! stress (Eq. 11) and the water force of Eq. 9 (scatterTwoPhase);
    //! 1b. the share of the empty parts of cells cut by the base.
    void scatter( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                  const StepSettings& settings )
    {
        scatterTwoPhase( exec, s.particles, s.water_particles, s.grid.geometry,
                         s.materials, s.water, settings.gravity_x,
                         settings.gravity_y, s.conditions.load_force,
                         _node_sums, baseAccess( s ) );
        baseCellForces( exec, s.base_cells, s.grid.geometry, settings.gravity_x,
                        settings.gravity_y, s.water.density );
    }

    //! How the water moves on the grid: with Darcy's drag and the edge
    //! inflows' ties (every step), or held to the solid (the quasi-static
    //! relaxation: the drag held_water_drag times Darcy's and no inflow,
    //! the flow being the step's own).
    enum class WaterOnGrid
    {
        darcy,
        held_to_solid
    };
    static constexpr double held_water_drag = 1.0e8;

    //! 2. Nodal velocities of both phases, the drag implicit (Eqs. 9-10,
    //! gridUpdateTwoPhase).
    void updateGrid( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                     const double dt, const StepSettings& settings,
                     const WaterOnGrid water = WaterOnGrid::darcy )
    {
        const double drag_factor =
            water == WaterOnGrid::darcy ? 1.0 : held_water_drag;
        gridUpdateTwoPhase(
            exec, s.grid, s.water_grid, _node_sums, dt, settings.damping,
            s.water.density, s.water.viscosity * drag_factor,
            s.solver.inertia_scaling, baseAccess( s ), inflowFlux( s, water ) );
    }

    //! 3. G2P: point velocities of both phases (FLIP/PIC share
    //! `flip_fraction`) and displacement increments; 4. the MUSL remap of
    //! both phases; 4b. the base cells' water (baseCellRates).
    void gatherAndRemap( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                         const double dt, const double flip_fraction,
                         const WaterOnGrid water = WaterOnGrid::darcy )
    {
        g2pVelocityRemapTwoPhase(
            exec, s.particles, s.water_particles, s.grid, s.water_grid, dt,
            flip_fraction, s.solver.water_relative_flip, s.materials, s.water,
            s.solver.inertia_scaling, _momentum_sums );
        remapVelocityTwoPhase( exec, s.grid, s.water_grid, _momentum_sums,
                               inflowFlux( s, water ), s.water.density );
        baseCellRates( exec, s.base_cells, s.grid, s.water_grid );
    }

    //! The pore-pressure point update (step 6) of `s`'s points and stage
    //! conditions with the scheme's increment rule `increment`.
    template <class Increment>
    static auto porePressure( const SimulationState<ExecSpace>& s,
                              const double dt, const Increment& increment )
    {
        return porePressurePointUpdate(
            s.particles, s.water_particles, s.water, dt,
            s.analysis == AnalysisType::Saturated, s.retention_current,
            s.conditions.prescribed_p_w, s.conditions.prescribed_hold,
            s.conditions.inflow_rate, s.conditions.inflow_ponding, increment );
    }

    /*!
      \brief 5-9 in one point loop (updatePointsTwoPhase): the velocity
      gradient, the pore pressure, porosity and retention state of
      `pore_pressure` (PorePressurePointUpdate with the scheme's rule), the
      effective stress, the positions and the diagnostics of the new state
      (10: the CFL limit of `wave_speed`, unless the cell water
      equilibrium follows and reduces its own).
    */
    template <class PorePressureUpdate, class WaveSpeed>
    PointUpdateReport
    updatePoints( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                  const double dt, const PorePressureUpdate& pore_pressure,
                  const WaveSpeed& wave_speed )
    {
        return updatePointsTwoPhase(
            exec, s.particles, s.water_particles, s.grid, s.water_grid,
            s.materials, dt, s.solver.bbar, s.solver.remove_points_leaving_grid,
            pore_pressure, baseAccess( s ), wave_speed,
            !s.solver.cell_equilibrium );
    }

    /*!
      \brief 6b. Cell water equilibrium (cellWaterEquilibrium, with the
      solver's cell_pressure_slope). It changes S after the point loop, so
      it sets the CFL limit of the new state in `report` itself, of
      `wave_speed`: its own reduction if it listed every active point, else
      `reduce()`.
    */
    template <class WaveSpeed, class Reduction>
    void cellEquilibrium( const ExecSpace& exec, SimulationState<ExecSpace>& s,
                          PointUpdateReport& report,
                          const WaveSpeed& wave_speed, const Reduction& reduce )
    {
        const CellEquilibriumLimit after = cellWaterEquilibrium(
            exec, s.particles, s.water_particles, s.grid.geometry, s.materials,
            s.water, s.analysis == AnalysisType::Saturated,
            s.solver.cell_pressure_slope, _cell_lists, wave_speed );
        const WaveSpeedLimit limit =
            after.listed == s.numActivePoints() - report.num_removed
                ? after.limit
                : reduce();
        report.diagnostics.dt_limit = limit.dt_limit;
        report.diagnostics.max_wave_speed = limit.max_wave_speed;
    }

  private:
    //! The edge inflows' nodal fluxes, or none for water held to the solid.
    Kokkos::View<double***, DeviceType<ExecSpace>>
    inflowFlux( const SimulationState<ExecSpace>& s, const WaterOnGrid water )
    {
        const auto& flux = s.conditions.inflow_flux_i;
        if ( water == WaterOnGrid::darcy )
            return flux;
        if ( _no_inflow.extent( 0 ) != flux.extent( 0 ) ||
             _no_inflow.extent( 1 ) != flux.extent( 1 ) )
            _no_inflow = Kokkos::View<double***, DeviceType<ExecSpace>>(
                "no_inflow_flux_i", flux.extent( 0 ), flux.extent( 1 ),
                flux.extent( 2 ) );
        return _no_inflow;
    }

    static BaseCellAccess<ExecSpace>
    baseAccess( const SimulationState<ExecSpace>& s )
    {
        return BaseCellAccess<ExecSpace>( s.base_cells, s.grid.geometry );
    }

    TwoPhaseNodeSums<ExecSpace> _node_sums;
    TwoPhaseMomentumSums<ExecSpace> _momentum_sums;
    Kokkos::View<double***, DeviceType<ExecSpace>> _no_inflow;
    CellPointLists<ExecSpace> _cell_lists;
};

} // namespace mpm

#endif // MPM_TWO_PHASE_STEP_PHASES_HPP
