#ifndef MPM_SIMULATION_HPP
#define MPM_SIMULATION_HPP

#include <io/mpm_case_config.hpp>
#include <mpm_diagnostics.hpp>
#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_p2g.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_position_update.hpp>
#include <mpm_stress_update.hpp>
#include <mpm_timestep.hpp>
#include <mpm_velocity_gradient.hpp>
#include <setup/mpm_materials.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <solver/mpm_simulation_error.hpp>

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
  explicit MUSL step of the dry (single-phase) analysis.
*/
template <class ExecSpace>
class Simulation
{
  public:
    using execution_space = ExecSpace;

    ParticleViews<ExecSpace> particles;
    GridViews<ExecSpace> grid;
    physics::MaterialTable materials;
    SolverConfig solver;
    double time = 0.0;   //!< simulated time since the start of the run, s
    long step = 0;       //!< steps taken since the start of the run
    int num_removed = 0; //!< points removed after leaving the grid

    //! Generates the points of `config` and applies its first stage.
    explicit Simulation( const CaseConfig& config )
        : particles( 0 )
        , grid( gridGeometry( config.grid ) )
        , solver( config.solver )
    {
        const InitialPoints points = generatePoints( config );
        if ( points.size() == 0 )
            throw SimulationError( config.file +
                                   ": no material point lies inside any body "
                                   "polygon; check bodies[].polygon_m" );
        particles = ParticleViews<ExecSpace>( points.size() );
        initialiseParticles( points, makeMaterialTable( config.materials ) );
        if ( !config.stages.empty() )
            applyStage( config.stages.front() );
    }

    //! Materials and boundary flags of a stage.
    void applyStage( const StageConfig& stage )
    {
        materials = makeMaterialTable( stage.materials );
        const std::vector<int> flags =
            nodeFlags( gridConfig(), stage.boundaries );
        auto flags_h = Kokkos::create_mirror_view( grid.flags_i );
        const int ny1 = grid.geometry.ny + 1;
        for ( int i = 0; i <= grid.geometry.nx; ++i )
            for ( int j = 0; j < ny1; ++j )
                flags_h( i, j ) = flags[i * ny1 + j];
        Kokkos::deep_copy( grid.flags_i, flags_h );
    }

    //! CFL limit (Courant number 1) and the largest wave speed.
    WaveSpeedLimit waveSpeedLimit() const
    {
        return criticalTimeStep( ExecSpace(), particles, materials,
                                 grid.geometry.h );
    }

    /*!
      \brief One explicit MUSL step of size dt: P2G, grid update, G2P,
      remap, velocity gradient (B-bar optional), stress update, positions.
      Throws SimulationError if a point leaves the grid (unless removal
      is enabled).
    */
    void advance( const double dt, const StepSettings& settings )
    {
        const ExecSpace exec;
        p2gMassMomentumForce( exec, particles, grid, settings.gravity_x,
                              settings.gravity_y );
        findActiveNodes( exec, grid );
        gridUpdateDry( exec, grid, dt, settings.damping );
        g2pVelocity( exec, particles, grid, dt, solver.flip_fraction );
        p2gMomentum( exec, particles, grid );
        remapVelocity( exec, grid );
        velocityGradient( exec, particles, grid );
        if ( solver.bbar )
            cellAverageVolumetricRate( exec, particles, grid );
        stressUpdate( exec, particles, materials, dt );
        int removed = 0;
        const int outside =
            updatePositions( exec, particles, grid.geometry,
                             solver.remove_points_leaving_grid, removed );
        num_removed += removed;
        time += dt;
        ++step;
        if ( outside >= 0 )
            throw SimulationError( describePoint(
                outside, "left the grid (set solver.remove_points_leaving_grid "
                         "= true to remove such points instead)" ) );
    }

    //! Throws SimulationError naming the first unstable point, if any.
    void checkStability( const double dt, const WaveSpeedLimit& limit ) const
    {
        const double speed_limit =
            solver.instability_speed_factor * limit.max_wave_speed;
        const int bad =
            findUnstablePoint( ExecSpace(), particles, speed_limit );
        if ( bad < 0 )
            return;
        std::ostringstream reason;
        reason << "is unstable: " << unstableQuantity( bad, speed_limit )
               << "\n  time step " << dt << " s against the CFL limit "
               << limit.dt_limit << " s (largest P-wave speed "
               << limit.max_wave_speed << " m/s)";
        throw SimulationError( describePoint( bad, reason.str() ) );
    }

    //! Sets the reference positions to the current ones (x0 = x).
    void resetDisplacement()
    {
        Kokkos::deep_copy( particles.x0_p, particles.x_p );
    }

    //! Number of points still simulated.
    int numActivePoints() const { return particles.size() - num_removed; }

    //! Diagnosis of one point: id, position, velocity, stress, step, time.
    std::string describePoint( const int p, const std::string& what ) const
    {
        const auto x = hostCopy( particles.x_p );
        const auto v = hostCopy( particles.v_p );
        const auto s = hostCopy( particles.sigma_p );
        const auto vol = hostCopy( particles.vol_p );
        const auto id = hostCopy( particles.id_p );
        std::ostringstream msg;
        msg << "material point " << id( p ) << " " << what << "\n"
            << "  at step " << step << ", t = " << time << " s\n"
            << "  position (" << x( p, 0 ) << ", " << x( p, 1 ) << ") m\n"
            << "  velocity (" << v( p, 0 ) << ", " << v( p, 1 ) << ") m/s\n"
            << "  stress xx, yy, xy, zz (" << s( p, 0 ) << ", " << s( p, 1 )
            << ", " << s( p, 2 ) << ", " << s( p, 3 ) << ") Pa\n"
            << "  volume " << vol( p ) << " m^3/m";
        return msg.str();
    }

  private:
    //! Which quantity of point p made it unstable, with its value.
    std::string unstableQuantity( const int p, const double speed_limit ) const
    {
        const auto x = hostCopy( particles.x_p );
        const auto v = hostCopy( particles.v_p );
        const auto s = hostCopy( particles.sigma_p );
        const auto vol = hostCopy( particles.vol_p );
        std::ostringstream what;
        const double speed = std::hypot( v( p, 0 ), v( p, 1 ) );
        if ( !std::isfinite( x( p, 0 ) ) || !std::isfinite( x( p, 1 ) ) )
            what << "position is not finite";
        else if ( !std::isfinite( speed ) )
            what << "velocity is not finite";
        else if ( speed > speed_limit )
            what << "speed " << speed << " m/s exceeds " << speed_limit
                 << " m/s (" << solver.instability_speed_factor
                 << " x the largest wave speed)";
        else if ( !( vol( p ) > 0.0 ) || !std::isfinite( vol( p ) ) )
            what << "volume " << vol( p )
                 << " m^3/m is not positive and finite";
        else
            what << "stress is not finite";
        return what.str();
    }

    template <class ViewType>
    static auto hostCopy( const ViewType& view )
    {
        return Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
    }

    static physics::GridGeometry gridGeometry( const GridConfig& config )
    {
        physics::GridGeometry g;
        g.x0 = config.origin_m[0];
        g.y0 = config.origin_m[1];
        g.h = config.cell_size_m;
        g.nx = config.cells[0];
        g.ny = config.cells[1];
        return g;
    }

    GridConfig gridConfig() const
    {
        GridConfig config;
        config.origin_m = { grid.geometry.x0, grid.geometry.y0 };
        config.cell_size_m = grid.geometry.h;
        config.cells = { grid.geometry.nx, grid.geometry.ny };
        return config;
    }

    void initialiseParticles( const InitialPoints& points,
                              const physics::MaterialTable& table )
    {
        auto x_h = Kokkos::create_mirror_view( particles.x_p );
        auto m_h = Kokkos::create_mirror_view( particles.m_p );
        auto vol_h = Kokkos::create_mirror_view( particles.vol_p );
        auto material_h = Kokkos::create_mirror_view( particles.material_p );
        auto id_h = Kokkos::create_mirror_view( particles.id_p );
        auto status_h = Kokkos::create_mirror_view( particles.status_p );
        for ( int p = 0; p < points.size(); ++p )
        {
            x_h( p, 0 ) = points.x[2 * p];
            x_h( p, 1 ) = points.x[2 * p + 1];
            vol_h( p ) = points.vol[p];
            material_h( p ) = points.material[p];
            m_h( p ) = table[points.material[p]].density * points.vol[p];
            id_h( p ) = p;
            status_h( p ) = point_active;
        }
        Kokkos::deep_copy( particles.x_p, x_h );
        Kokkos::deep_copy( particles.x0_p, x_h );
        Kokkos::deep_copy( particles.m_p, m_h );
        Kokkos::deep_copy( particles.vol_p, vol_h );
        Kokkos::deep_copy( particles.vol0_p, vol_h );
        Kokkos::deep_copy( particles.material_p, material_h );
        Kokkos::deep_copy( particles.id_p, id_h );
        Kokkos::deep_copy( particles.status_p, status_h );
    }
};

} // namespace mpm

#endif // MPM_SIMULATION_HPP
