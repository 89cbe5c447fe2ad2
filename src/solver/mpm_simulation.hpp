#ifndef MPM_SIMULATION_HPP
#define MPM_SIMULATION_HPP

#include <io/mpm_case_config.hpp>
#include <mpm_diagnostics.hpp>
#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_grid_update_two_phase.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_p2g.hpp>
#include <mpm_p2g_two_phase.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_position_update.hpp>
#include <mpm_stress_update.hpp>
#include <mpm_timestep.hpp>
#include <mpm_velocity_gradient.hpp>
#include <mpm_water_views.hpp>
#include <solver/mpm_diagnosis.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/mpm_simulation_setup.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <sstream>
#include <string>

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
  formulation.md). Water fields exist only in two-phase scenes.
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
        if ( twoPhase() )
        {
            water_particles = WaterParticleViews<ExecSpace>( points.size() );
            water_grid = WaterGridViews<ExecSpace>( grid.geometry );
        }
        initialiseParticles( config, points, particles, water_particles,
                             water );
        if ( !config.stages.empty() )
            applyStage( config.stages.front() );
    }

    bool twoPhase() const { return analysis != AnalysisType::Dry; }

    //! Materials, boundary flags and point conditions of a stage.
    void applyStage( const StageConfig& stage )
    {
        materials = makeMaterialTable( stage.materials );
        copyNodeFlags( nodeFlags( grid_config, stage.boundaries ),
                       grid.flags_i );
        if ( twoPhase() )
            copyNodeFlags( waterNodeFlags( grid_config, stage.boundaries ),
                           water_grid.flags_w_i );
        conditions.apply( stage, particles, water_particles, grid_config );
    }

    //! CFL limit (Courant number 1) and the largest wave speed, both of
    //! the inertia-scaled system (waves sqrt(f) slower).
    WaveSpeedLimit waveSpeedLimit() const
    {
        WaveSpeedLimit limit =
            twoPhase() ? criticalTimeStepTwoPhase( ExecSpace(), particles,
                                                   water_particles, materials,
                                                   water, grid.geometry.h )
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
        if ( twoPhase() )
            advanceTwoPhase( dt, settings );
        else
            advanceDry( dt, settings );
        int removed = 0;
        const int outside =
            updatePositions( ExecSpace(), particles, grid.geometry,
                             solver.remove_points_leaving_grid, removed );
        num_removed += removed;
        time += dt;
        ++step;
        if ( outside >= 0 )
            throw SimulationError( describe(
                outside, "left the grid (set solver.remove_points_leaving_grid "
                         "= true to remove such points instead)" ) );
    }

    //! Throws SimulationError naming the first unstable point, if any.
    void checkStability( const double dt, const WaveSpeedLimit& limit ) const
    {
        const double speed_limit =
            solver.instability_speed_factor * limit.max_wave_speed;
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
    //! Single phase: P2G, grid update, G2P, remap, gradient, stress.
    void advanceDry( const double dt, const StepSettings& settings )
    {
        const ExecSpace exec;
        p2gMassMomentumForce( exec, particles, grid, settings.gravity_x,
                              settings.gravity_y, conditions.load_force );
        findActiveNodes( exec, grid );
        gridUpdateDry( exec, grid, dt, settings.damping,
                       solver.inertia_scaling );
        g2pVelocity( exec, particles, grid, dt, solver.flip_fraction );
        p2gMomentum( exec, particles, grid );
        remapVelocity( exec, grid );
        velocityGradient( exec, particles, grid );
        if ( solver.bbar )
            cellAverageVolumetricRate( exec, particles, grid );
        stressUpdate( exec, particles, materials, dt );
    }

    //! Two phases, formulation.md steps 1-9 (drag implicit at the nodes).
    void advanceTwoPhase( const double dt, const StepSettings& settings )
    {
        const ExecSpace exec;
        p2gTwoPhase( exec, particles, water_particles, grid, water_grid,
                     materials, water, settings.gravity_x, settings.gravity_y,
                     conditions.load_force );
        findActiveNodes( exec, grid );
        gridUpdateTwoPhase( exec, grid, water_grid, dt, settings.damping,
                            water.density, water.viscosity,
                            solver.inertia_scaling );
        g2pVelocityTwoPhase( exec, particles, water_particles, grid, water_grid,
                             dt, solver.flip_fraction );
        p2gMomentumTwoPhase( exec, particles, water_particles, grid, water_grid,
                             water.density );
        remapVelocityTwoPhase( exec, grid, water_grid );
        velocityGradientTwoPhase( exec, particles, water_particles, grid,
                                  water_grid, water.density );
        if ( solver.bbar )
        {
            cellAverageVolumetricRate( exec, particles, grid );
            cellAverageWaterDivergence( exec, particles, water_particles, grid,
                                        water_grid );
        }
        porePressureUpdate( exec, particles, water_particles, materials, water,
                            dt, analysis == AnalysisType::Saturated,
                            conditions.prescribed_p_w, conditions.inflow_rate,
                            conditions.inflow_ponding );
        stressUpdate( exec, particles, materials, dt );
    }

    void copyNodeFlags( const std::vector<int>& flags,
                        const typename GridViews<ExecSpace>::int_view& view )
    {
        auto flags_h = Kokkos::create_mirror_view( view );
        const int ny1 = grid.geometry.ny + 1;
        for ( int i = 0; i <= grid.geometry.nx; ++i )
            for ( int j = 0; j < ny1; ++j )
                flags_h( i, j ) = flags[i * ny1 + j];
        Kokkos::deep_copy( view, flags_h );
    }
};

} // namespace mpm

#endif // MPM_SIMULATION_HPP
