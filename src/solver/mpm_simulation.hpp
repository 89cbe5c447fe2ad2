#ifndef MPM_SIMULATION_HPP
#define MPM_SIMULATION_HPP

#include <io/mpm_case_config.hpp>
#include <mpm_base_cells.hpp>
#include <mpm_cell_equilibrium.hpp>
#include <mpm_diagnostics.hpp>
#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_grid_update_two_phase.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_p2g.hpp>
#include <mpm_p2g_two_phase.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_update.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_timestep.hpp>
#include <mpm_velocity_gradient.hpp>
#include <mpm_water_content.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_kinematics.hpp>
#include <setup/mpm_retention_tables.hpp>
#include <setup/mpm_stage_flags.hpp>
#include <solver/mpm_diagnosis.hpp>
#include <solver/mpm_dry_step.hpp>
#include <solver/mpm_host_transfer.hpp>
#include <solver/mpm_pressure_projection.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/mpm_simulation_setup.hpp>

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
  \brief The state of one simulation (points, grid, materials) and the
  explicit MUSL step, dry (single phase) or two-phase (solid + water,
  docs/formulation.md). Water fields exist only in two-phase scenes.

  The step keeps its grid sums (GridScatter) between steps and touches
  only the nodes and cells of the points. Its last point loop also
  evaluates the CFL limit, the kinetic energy and the stability of the new
  state (StepDiagnostics): waveSpeedLimit, kineticEnergy and
  checkStability use them until the state changes (the next step or
  applyStage), so the time loop runs no reduction of its own. Code that
  writes point fields directly between steps must call
  stateChanged() afterwards.
*/
template <class ExecSpace>
class Simulation
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

    //! Generates the points of `config` and applies its first stage.
    explicit Simulation( const CaseConfig& config )
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
        const int num_nodes = grid.geometry.numNodes();
        if ( twoPhase() )
        {
            water_particles = WaterParticleViews<ExecSpace>( points.size() );
            water_grid = WaterGridViews<ExecSpace>( grid.geometry );
            _two_phase_sums =
                TwoPhaseNodeSums<ExecSpace>( "p2g_two_phase", num_nodes );
            _two_phase_momentum =
                TwoPhaseMomentumSums<ExecSpace>( "remap_two_phase", num_nodes );
            if ( solver.cell_equilibrium || semiImplicit() )
                _cell_lists = CellPointLists<ExecSpace>(
                    points.size(), grid.geometry.nx * grid.geometry.ny );
            if ( semiImplicit() )
                _projection = PressureProjection<ExecSpace>( grid.geometry );
        }
        else
            _dry_step = DryStepPhases<ExecSpace>( grid.geometry );

        initialiseParticles( config, points, particles, water_particles );
        if ( !config.stages.empty() )
            applyStage( config.stages.front() );
    }

    bool twoPhase() const { return analysis != AnalysisType::Dry; }

    //! True for the semi-implicit two-phase scheme (a pressure solve).
    bool semiImplicit() const
    {
        return twoPhase() && solver.scheme == TwoPhaseScheme::SemiImplicit;
    }

    //! The pressure solves so far (semi-implicit), else null.
    const PressureSolveStats* pressureSolveStats() const
    {
        return semiImplicit() ? &_projection.stats() : nullptr;
    }

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

    //! CFL limit (Courant number 1) and the largest wave speed, both of
    //! the inertia-scaled system (waves sqrt(f) slower).
    WaveSpeedLimit waveSpeedLimit() const
    {
        WaveSpeedLimit limit =
            diagnosticsCurrent() ? WaveSpeedLimit{ _diagnostics.dt_limit,
                                                   _diagnostics.max_wave_speed }
            : twoPhase()
                ? criticalTimeStepTwoPhase( ExecSpace(), particles,
                                            water_particles, materials, water,
                                            grid.geometry.h, semiImplicit() )
                : criticalTimeStep( ExecSpace(), particles, materials,
                                    grid.geometry.h );
        const double root_f = std::sqrt( solver.inertia_scaling );
        limit.dt_limit *= root_f;
        limit.max_wave_speed /= root_f;
        return limit;
    }

    /*!
      \brief One explicit MUSL step of size dt at stage time stage_time_s.
      Throws SimulationError if a point leaves the grid (unless removal is
      enabled).
    */
    void advance( const double dt, const StepSettings& settings,
                  const double stage_time_s = 0.0 )
    {
        conditions.update( stage_time_s + dt );
        const PointUpdateReport report =
            twoPhase() ? advanceStep<TwoPhaseScene>( dt, settings )
                       : advanceStep<DryScene>( dt, settings );
        num_removed += report.num_removed;
        time += dt;
        ++step;
        _step_water = report.water;
        _diagnostics = report.diagnostics;
        _diagnostics_step = step;
        if ( report.first_outside >= 0 )
            throw SimulationError( describe(
                report.first_outside,
                "left the grid (set solver.remove_points_leaving_grid "
                "= true to remove such points instead)" ) );
    }

    //! Throws SimulationError naming the first unstable point, if any.
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
      \brief Declares the point state changed outside advance (fields
      written directly): the step's diagnostics and the stored retention
      state are no longer trusted.
    */
    void stateChanged()
    {
        _diagnostics_step = -1;
        _retention_current = false;
    }

    //! Rebuilds what derives from the node flags (the base cells) after
    //! they were set or restored (restoreCheckpoint).
    void flagsRestored()
    {
        _base_cells = _cut_cells.empty()
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

  private:
    //! True if _diagnostics describe the current state.
    bool diagnosticsCurrent() const { return _diagnostics_step == step; }

    //! FLIP fraction of a step of size dt (physics::stepFlipFraction).
    double stepFlipFraction( const double dt ) const
    {
        return physics::stepFlipFraction( solver.flip_fraction, dt,
                                          dampingReferenceStep() );
    }

    /*!
      \brief The step at which the FLIP/PIC blend is `flip_fraction`: the
      explicit scheme's CFL limit (Courant number 1), in both schemes, so
      the PIC damping per second is the same whichever scheme runs. The
      semi-implicit step is about 20 times longer on the slope; with its own
      (skeleton) limit as reference it damped 20 times less per second, and
      a softened face without tensile strength that the explicit run holds
      slid off in the first seconds of rain (docs/formulation.md §9).
    */
    double dampingReferenceStep() const
    {
        if ( !semiImplicit() )
            return waveSpeedLimit().dt_limit;
        const WaveSpeedLimit undrained =
            criticalTimeStepTwoPhase( ExecSpace(), particles, water_particles,
                                      materials, water, grid.geometry.h );
        return undrained.dt_limit * std::sqrt( solver.inertia_scaling );
    }

    //! B-bar: the cell averages of the step's velocity gradients.
    void cellAverages( const ExecSpace& exec )
    {
        if ( !_cell_sums.allocated() )
            _cell_sums = CellSums<ExecSpace>(
                "bbar_cells", grid.geometry.nx * grid.geometry.ny );
        velocityGradientCellSums( exec, particles, water_particles, grid,
                                  water_grid, _cell_sums );
        takeCellSums( exec, grid, water_grid, _cell_sums );
    }

    //! The scene formulations of the step (advanceStep): which kernels
    //! each phase runs.
    struct DryScene
    {
        static constexpr bool two_phase = false;
    };
    struct TwoPhaseScene
    {
        static constexpr bool two_phase = true;
    };

    /*!
      \brief The explicit MUSL step, in the order of docs/formulation.md §3
      (the paper's §2.6; a dry scene: §4, the same phases on one phase).
      Each phase is one kernel whose body is a physics functor; `Scene`
      picks the dry or the two-phase kernel of each phase. The step numbers
      are those of docs/formulation.md.
    */
    template <class Scene>
    PointUpdateReport advanceStep( const double dt,
                                   const StepSettings& settings )
    {
        const ExecSpace exec;
        const BaseCellAccess<ExecSpace> base( _base_cells, grid.geometry );
        const bool saturated = analysis == AnalysisType::Saturated;

        // 1. P2G: masses, momenta and forces; two-phase: the mixture force
        // with Bishop's total stress (Eq. 11) and the water force of Eq. 9
        // (1b: the share of the empty parts of cells cut by the base).
        if constexpr ( Scene::two_phase )
        {
            scatterTwoPhase( exec, particles, water_particles, grid.geometry,
                             materials, water, settings.gravity_x,
                             settings.gravity_y, conditions.load_force,
                             _two_phase_sums, base );
            baseCellForces( exec, _base_cells, grid.geometry,
                            settings.gravity_x, settings.gravity_y,
                            water.density );
        }
        else
            _dry_step.scatter( exec, particles, grid.geometry,
                               settings.gravity_x, settings.gravity_y,
                               conditions.load_force );

        // 2. Nodal velocities; two-phase: both phases, the drag implicit
        // (Eqs. 9-10).
        if constexpr ( Scene::two_phase )
            gridUpdateTwoPhase( exec, grid, water_grid, _two_phase_sums, dt,
                                settings.damping, water.density,
                                water.viscosity, solver.inertia_scaling, base,
                                conditions.inflow_flux_i );
        else
            _dry_step.updateGrid( exec, grid, dt, settings.damping,
                                  solver.inertia_scaling );

        // 2b. Semi-implicit: each cell's pressure increment of Eq. 8 at the
        // new time and the velocities it corrects (§9; the points take it
        // in step 6).
        [[maybe_unused]] auto pore_pressure = porePressurePointUpdate(
            particles, water_particles, water, dt, saturated,
            _retention_current, conditions.prescribed_p_w,
            conditions.prescribed_hold, conditions.inflow_rate,
            conditions.inflow_ponding );
        if constexpr ( Scene::two_phase )
            if ( semiImplicit() )
                correctPressure( exec, dt, pore_pressure );

        // 3. G2P: point velocities (FLIP/PIC) and displacement increments;
        // 4. the MUSL remap (two-phase: of both phases; 4b: the base
        // cells' water).
        if constexpr ( Scene::two_phase )
        {
            g2pVelocityRemapTwoPhase(
                exec, particles, water_particles, grid, water_grid, dt,
                stepFlipFraction( dt ), solver.water_relative_flip, materials,
                water, solver.inertia_scaling, _two_phase_momentum );
            remapVelocityTwoPhase( exec, grid, water_grid, _two_phase_momentum,
                                   conditions.inflow_flux_i, water.density );
            baseCellRates( exec, _base_cells, grid, water_grid );
        }
        else
            _dry_step.gatherAndRemap( exec, particles, grid, dt,
                                      stepFlipFraction( dt ) );

        // 5. Velocity gradients (two-phase: and the water divergence):
        // with B-bar, their cell averages first.
        if ( solver.bbar )
            cellAverages( exec );

        // 5-9 in one point loop: the gradient (StepVelocityGradient);
        // two-phase: PorePressurePointUpdate (the Eq. 8 pore pressure, the
        // Eq. 2 porosity, the retention state); the effective stress
        // (StressPointUpdate); the positions; the diagnostics of the new
        // state (10: the CFL limit of the next step, unless 6b reduces it).
        if constexpr ( !Scene::two_phase )
            return _dry_step.updatePoints( exec, particles, grid, materials, dt,
                                           solver.bbar,
                                           solver.remove_points_leaving_grid );
        else
        {
            PointUpdateReport report = updatePointsTwoPhase(
                exec, particles, water_particles, grid, water_grid, materials,
                water, dt, solver.bbar, solver.remove_points_leaving_grid,
                pore_pressure, base, !solver.cell_equilibrium, semiImplicit() );

            // 6b. Cell water equilibrium. It changes S after the point
            // loop, so it reduces the CFL limit of the new state itself (a
            // separate reduction if it did not list every active point).
            if ( solver.cell_equilibrium )
            {
                const CellEquilibriumLimit after = cellWaterEquilibrium(
                    exec, particles, water_particles, grid.geometry, materials,
                    water, saturated, solver.cell_pressure_slope, _cell_lists,
                    semiImplicit() );
                const WaveSpeedLimit limit =
                    after.listed == numActivePoints() - report.num_removed
                        ? after.limit
                        : criticalTimeStepTwoPhase(
                              exec, particles, water_particles, materials,
                              water, grid.geometry.h, semiImplicit() );
                report.diagnostics.dt_limit = limit.dt_limit;
                report.diagnostics.max_wave_speed = limit.max_wave_speed;
            }
            // S_p and dS_dp_p now hold the retention law at p_w_p.
            _retention_current = !saturated;
            return report;
        }
    }

    //! Step 2b of the semi-implicit scheme (PressureProjection::correct),
    //! after which `pore_pressure` takes the increment at the points.
    template <class PorePressureUpdate>
    void correctPressure( const ExecSpace& exec, const double dt,
                          PorePressureUpdate& pore_pressure )
    {
        const PorePressureUpdate terms = pore_pressure;
        const auto source = KOKKOS_LAMBDA( const int q )
        {
            return terms.inflowSource( q, terms.inflow_p( q ) );
        };
        _projection.correct(
            exec, particles, water_particles, grid, water_grid, materials,
            water, analysis == AnalysisType::Saturated, solver.inertia_scaling,
            dt, source, conditions.inflow_flux_i,
            pressureSolveSettings( solver ), _cell_lists, step + 1, time );
        pore_pressure.projected = true;
        pore_pressure.dp_c = _projection.increments();
        pore_pressure.x_p = particles.x_p;
        pore_pressure.grid = grid.geometry;
    }

    //! The semi-implicit scheme's pressure solve (empty otherwise).
    PressureProjection<ExecSpace> _projection;
    //! The tabulated retention laws of `materials` (solver.retention_table).
    RetentionTables<ExecSpace> _retention_tables;
    // Grid sums kept between steps (empty if the scene does not need them).
    DryStepPhases<ExecSpace> _dry_step;
    TwoPhaseNodeSums<ExecSpace> _two_phase_sums;
    TwoPhaseMomentumSums<ExecSpace> _two_phase_momentum;
    CellSums<ExecSpace> _cell_sums;
    //! The points of each cell (cell water equilibrium).
    CellPointLists<ExecSpace> _cell_lists;
    //! The stage's cells cut by a fixed base line (cutBaseCells; empty
    //! without base_cell_completion or in a dry scene).
    std::vector<int> _cut_cells;
    //! Cells cut by the fixed base (their divergence completed).
    BaseCells<ExecSpace> _base_cells;
    //! Diagnostics of the state after step _diagnostics_step (-1: none).
    StepDiagnostics _diagnostics{ 0.0, 0.0, 0.0, 0.0, 0 };
    physics::WaterStepVolumes _step_water; //!< of the last step
    long _diagnostics_step = -1;
    //! True if S_p, dS_dp_p are the retention law's values at p_w_p.
    bool _retention_current = false;
};

} // namespace mpm

#endif // MPM_SIMULATION_HPP
