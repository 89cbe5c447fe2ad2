#include <bench_problem.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <exception>
#include <map>
#include <string>

namespace mpm_bench
{
//---------------------------------------------------------------------------//
mpm::CaseConfig projectCase( const std::string& file )
{
    try
    {
        return mpm::readCaseFile( RAINSLIDE_CASES_DIR "/" + file );
    }
    catch ( const std::exception& )
    {
        return mpm::CaseConfig();
    }
}

//---------------------------------------------------------------------------//
mpm::CaseConfig soilBlockCase( const int n )
{
    const double h = block_height_m / n;
    const int margin = ( n + 1 ) / 2;

    mpm::MaterialConfig soil;
    soil.name = "soil";
    soil.model = mpm::ModelType::MohrCoulomb;
    soil.density_kg_per_m3 = 1900.0;
    soil.youngs_modulus_pa = 1.0e7;
    soil.poisson_ratio = 0.33;
    soil.cohesion_peak_pa = 20.0e3;
    soil.cohesion_residual_pa = 20.0e3;
    soil.softening_modulus_pa = 0.0;
    soil.friction_angle_deg = 20.0;
    soil.dilation_angle_deg = 0.0;

    mpm::CaseConfig c;
    c.file = "<benchmark>";
    c.name = "soil_block_n" + std::to_string( n );
    c.description = "Mohr-Coulomb block under gravity (benchmark)";
    c.grid.origin_m = { 0.0, 0.0 };
    c.grid.cell_size_m = h;
    c.grid.cells = { 2 * n + 2 * margin, n + margin };
    c.points_per_cell_per_direction = 2;
    c.materials = { soil };

    // Block [margin, margin + 2n) x [0, n) in cells, on the grid's base.
    const double x_left = margin * h;
    const double x_right = ( margin + 2 * n ) * h;
    mpm::BodyConfig body;
    body.material = soil.name;
    body.material_id = 0;
    body.polygon_m = { { x_left, 0.0 },
                       { x_right, 0.0 },
                       { x_right, block_height_m },
                       { x_left, block_height_m } };
    c.bodies = { body };

    c.boundaries = mpm::rollerSidesFixedBase();

    c.solver.courant_number = 0.5;
    c.solver.flip_fraction = 0.99;

    mpm::StageConfig stage;
    stage.name = "gravity";
    stage.type = mpm::StageType::Dynamic;
    stage.gravity_m_per_s2 = { 0.0, -9.81 };
    stage.damping = 0.0;
    stage.duration_s = 1.0;
    stage.materials = c.materials;
    stage.boundaries = c.boundaries;
    c.stages = { stage };
    return c;
}

namespace
{
//! Host copy of every entry of a View.
template <class ViewType>
auto hostVector( const ViewType& view )
{
    auto h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
    return std::vector<typename ViewType::non_const_value_type>(
        h.data(), h.data() + h.span() );
}

//! Geostatic stress sigma_yy = -rho g (H - y), sigma_xx = sigma_zz = K0
//! sigma_yy (tension positive), on the points of `sim`.
template <class ExecSpace>
void setGeostaticStress( mpm::Simulation<ExecSpace>& sim,
                         const mpm::MaterialConfig& soil, const double g )
{
    const double k0 = soil.poisson_ratio / ( 1.0 - soil.poisson_ratio );
    const double rho_g = soil.density_kg_per_m3 * g;
    const auto x_p = sim.particles.x_p;
    const auto sigma_p = sim.particles.sigma_p;
    Kokkos::parallel_for(
        "mpm_bench::geostatic_stress",
        Kokkos::RangePolicy<ExecSpace>( ExecSpace(), 0, sim.particles.size() ),
        KOKKOS_LAMBDA( const int p ) {
            const double s_yy = -rho_g * ( block_height_m - x_p( p, 1 ) );
            sigma_p( p, 0 ) = k0 * s_yy;
            sigma_p( p, 1 ) = s_yy;
            sigma_p( p, 2 ) = 0.0;
            sigma_p( p, 3 ) = k0 * s_yy;
        } );
    ExecSpace().fence();
}

//! Runs the preload on the default host backend and copies the state out.
PreparedState prepare( const int n )
{
    using exec_space = Kokkos::DefaultHostExecutionSpace;
    PreparedState state;
    state.config = soilBlockCase( n );
    const mpm::StageConfig& stage = state.config.stages.front();
    const mpm::StepSettings settings{
        stage.gravity_m_per_s2[0], stage.gravity_m_per_s2[1], stage.damping };

    mpm::Simulation<exec_space> sim( state.config );
    setGeostaticStress( sim, state.config.materials.front(),
                        -stage.gravity_m_per_s2[1] );
    while ( sim.time < preload_time_s )
    {
        const double dt =
            mpm::chooseTimeStep( sim.solver, sim.waveSpeedLimit() );
        sim.advance( dt, settings );
    }
    state.dt = mpm::chooseTimeStep( sim.solver, sim.waveSpeedLimit() );
    state.num_points = sim.particles.size();
    state.preload_steps = static_cast<int>( sim.step );

    const auto& pv = sim.particles;
    state.x = hostVector( pv.x_p );
    state.x0 = hostVector( pv.x0_p );
    state.v = hostVector( pv.v_p );
    state.vol = hostVector( pv.vol_p );
    state.sigma = hostVector( pv.sigma_p );
    state.eps = hostVector( pv.eps_p );
    state.eps_p_bar = hostVector( pv.eps_p_bar_p );
    state.status = hostVector( pv.status_p );
    int yielded = 0;
    for ( const double e : state.eps_p_bar )
        yielded += e > 0.0 ? 1 : 0;
    state.yielded = double( yielded ) / state.num_points;
    return state;
}

} // namespace

//---------------------------------------------------------------------------//
const PreparedState& preparedState( const int n )
{
    // Host vectors only: safe to keep until the end of the process.
    static std::map<int, PreparedState> cache;
    auto found = cache.find( n );
    if ( found == cache.end() )
        found = cache.emplace( n, prepare( n ) ).first;
    return found->second;
}

} // namespace mpm_bench
