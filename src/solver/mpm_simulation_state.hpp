#ifndef MPM_SIMULATION_STATE_HPP
#define MPM_SIMULATION_STATE_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_base_cells.hpp>
#include <mpm_diagnostics.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_update.hpp>
#include <mpm_water_content.hpp>
#include <mpm_water_views.hpp>
#include <setup/mpm_retention_tables.hpp>
#include <setup/mpm_stage_flags.hpp>
#include <solver/mpm_diagnosis.hpp>
#include <solver/mpm_host_transfer.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/mpm_simulation_setup.hpp>
#include <solver/mpm_stage_conditions.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace mpm
{
//! Per-step settings of the current stage.
struct StepSettings
{
    double gravity_x = 0.0; //!< m/s^2
    double gravity_y = 0.0; //!< m/s^2
    double damping = 0.0;   //!< local damping coefficient
};

//---------------------------------------------------------------------------//
/*!
  \brief The state of one simulation, apart from the step that advances it
  (solver/steps): the points, the grid, the stage's materials and
  conditions, and what the last step found about the new state.

  A step's last point loop also evaluates the CFL limit, the kinetic
  energy and the stability of the new state (StepDiagnostics, stored by
  stepTaken): kineticEnergy, maxPointSpeed and checkStability use them
  until the state changes (the next step or applyStage), so the time loop
  runs no reduction of its own. Code that writes point fields directly
  between steps must call stateChanged() afterwards.
*/
template <class ExecSpace>
class SimulationState
{
  public:
    using execution_space = ExecSpace;

    AnalysisType analysis = AnalysisType::Dry;
    ParticleViews<ExecSpace> particles;
    WaterParticleViews<ExecSpace> water_particles; //!< two-phase only
    GridViews<ExecSpace> grid;
    WaterGridViews<ExecSpace> water_grid; //!< two-phase only
    StageConditions<ExecSpace> conditions;
    physics::MaterialTable materials;
    physics::WaterParams water;
    SolverConfig solver;
    GridConfig grid_config;
    double time = 0.0;   //!< simulated time since the start of the run, s
    long step = 0;       //!< steps taken since the start of the run
    int num_removed = 0; //!< points removed after leaving the grid
    //! Cells cut by the fixed base (their divergence completed).
    BaseCells<ExecSpace> base_cells;
    //! True if S_p, dS_dp_p are the retention law's values at p_w_p.
    bool retention_current = false;

    //! Generates the points of `config` and applies its first stage.
    explicit SimulationState( const CaseConfig& config )
        : analysis( config.analysis )
        , grid( gridGeometry( config.grid ) )
        , water( waterParams( config.water ) )
        , solver( config.solver )
        , grid_config( config.grid )
    {
        const InitialPoints points = generatePoints( config );
        if ( points.size() == 0 )
            throw SimulationError( config.file +
                                   ": no material point lies inside any body "
                                   "polygon; check bodies[].polygon_m" );
        particles = ParticleViews<ExecSpace>( points.size() );
        if ( twoPhase() )
        {
            water_particles = WaterParticleViews<ExecSpace>( points.size() );
            water_grid = WaterGridViews<ExecSpace>( grid.geometry );
        }
        initialiseParticles( config, points, particles, water_particles );
        if ( !config.stages.empty() )
            applyStage( config.stages.front() );
    }

    bool twoPhase() const { return analysis != AnalysisType::Dry; }

    //! Materials, boundary flags and point conditions of a stage.
    void applyStage( const StageConfig& stage )
    {
        stateChanged();
        materials = makeMaterialTable( stage.materials );
        for ( int k = 0; k < materials.size; ++k )
            materials.materials[k].moduli_fall_with_dilation =
                solver.moduli_fall_with_dilation;
        if ( analysis == AnalysisType::Unsaturated && solver.retention_table )
            _retention_tables.attach( materials );
        // Two-phase only for now: the dry step has no completion either.
        const bool complete = solver.base_cell_completion && twoPhase();
        StageNodeFlags flags = stageNodeFlags(
            grid_config, grid.geometry, stage, twoPhase(), complete,
            complete ? activePointPositions( particles )
                     : std::vector<double>() );
        _cut_cells = std::move( flags.cut_cells );
        copyNodeFlags( grid.geometry, flags.solid, grid.flags_i );
        flagsRestored();
        if ( twoPhase() )
            copyNodeFlags( grid.geometry, flags.water, water_grid.flags_w_i );
        conditions.apply( stage, particles, water_particles, grid_config );
    }

    //! Throws SimulationError naming the first unstable point, if any:
    //! `limit` is the step's CFL limit and largest wave speed.
    void checkStability( const double dt, const WaveSpeedLimit& limit ) const
    {
        const double speed_limit =
            solver.instability_speed_factor * limit.max_wave_speed;
        // The step's diagnostics clear the usual, stable state at no cost.
        if ( diagnosticsCurrent() &&
             _diagnostics.first_unsound >= particles.size() &&
             !( _diagnostics.max_speed2 > speed_limit * speed_limit ) )
            return;
        const int bad = findUnstablePoint( ExecSpace(), particles,
                                           water_particles, speed_limit );
        if ( bad < 0 )
            return;
        std::ostringstream reason;
        reason << "is unstable: "
               << unstableQuantity( particles, water_particles, bad,
                                    speed_limit,
                                    solver.instability_speed_factor )
               << "\n  time step " << dt << " s against the CFL limit "
               << limit.dt_limit << " s (largest wave speed "
               << limit.max_wave_speed << " m/s)";
        throw SimulationError( describe( bad, reason.str() ) );
    }

    //! Total kinetic energy of the points, J (kineticEnergy).
    double kineticEnergy() const
    {
        return diagnosticsCurrent()
                   ? _diagnostics.kinetic_energy
                   : mpm::kineticEnergy( ExecSpace(), particles );
    }

    //! Largest solid speed of the active points, m/s (maxPointSpeed).
    double maxPointSpeed() const
    {
        return diagnosticsCurrent()
                   ? std::sqrt( _diagnostics.max_speed2 )
                   : mpm::maxPointSpeed( ExecSpace(), particles );
    }

    //! The water the last step's Eq. 8 moved (zero in a dry scene).
    const physics::WaterStepVolumes& stepWater() const { return _step_water; }

    //! Water held by the points now (zero in a dry scene).
    WaterContent waterContent() const
    {
        return mpm::waterContent( ExecSpace(), particles, water_particles,
                                  water );
    }

    //! Number of active points with a solid speed >= `speed` (m/s).
    long pointsNotBelowSpeed( const double speed ) const
    {
        return countPointsNotBelowSpeed( ExecSpace(), particles, speed );
    }

    //! Largest displacement |x - x0| of the active points, m.
    double maxDisplacement() const
    {
        return mpm::maxDisplacement( ExecSpace(), particles );
    }

    //! Initial area of the active points displaced more than
    //! `displacement` (m), m^2 per metre (movedArea).
    double movedArea( const double displacement ) const
    {
        return mpm::movedArea( ExecSpace(), particles, displacement );
    }

    /*!
      \brief Declares the point state changed outside a step (fields
      written directly): the step's diagnostics and the stored retention
      state are no longer trusted.
    */
    void stateChanged()
    {
        _diagnostics_step = -1;
        retention_current = false;
    }

    //! Rebuilds what derives from the node flags (the base cells) after
    //! they were set or restored (restoreCheckpoint).
    void flagsRestored()
    {
        base_cells = _cut_cells.empty()
                         ? BaseCells<ExecSpace>()
                         : BaseCells<ExecSpace>( grid.geometry, grid.flags_i,
                                                 _cut_cells );
    }

    //! Sets the reference positions to the current ones (x0 = x).
    void resetDisplacement()
    {
        Kokkos::deep_copy( particles.x0_p, particles.x_p );
    }

    //! Number of points still simulated.
    int numActivePoints() const { return particles.size() - num_removed; }

    //! Diagnosis of one point.
    std::string describe( const int p, const std::string& what ) const
    {
        return describePoint( particles, water_particles, p, what, step, time );
    }

  protected:
    //! Books a step of size dt that reported `report`: the time, the step
    //! count, the removed points, the step's water and the diagnostics of
    //! the new state.
    void stepTaken( const double dt, const PointUpdateReport& report )
    {
        num_removed += report.num_removed;
        time += dt;
        ++step;
        _step_water = report.water;
        _diagnostics = report.diagnostics;
        _diagnostics_step = step;
    }

    //! True if the last step's diagnostics describe the current state.
    bool diagnosticsCurrent() const { return _diagnostics_step == step; }

    //! The CFL limit and largest wave speed of the last step's diagnostics.
    WaveSpeedLimit diagnosedLimit() const
    {
        return { _diagnostics.dt_limit, _diagnostics.max_wave_speed };
    }

  private:
    //! The tabulated retention laws of `materials` (solver.retention_table).
    RetentionTables<ExecSpace> _retention_tables;
    //! The stage's cells cut by a fixed base line (cutBaseCells; empty
    //! without base_cell_completion or in a dry scene).
    std::vector<int> _cut_cells;
    //! Diagnostics of the state after step _diagnostics_step (-1: none).
    StepDiagnostics _diagnostics{ 0.0, 0.0, 0.0, 0.0, 0 };
    physics::WaterStepVolumes _step_water; //!< of the last step
    long _diagnostics_step = -1;
};

} // namespace mpm

#endif // MPM_SIMULATION_STATE_HPP
