// The semi-implicit step's Newton residual (docs/formulation.md §9, item 4)
// on a few unsaturated and saturated points in four cells of a 3 x 3 grid:
// R_c = b_c - sum_p V dtheta_p / dt - (K dp)_c and A's diagonal K_cc +
// sum_p V C_p / dt, from one pass (newtonStorageSums, newtonResidual)
// against the same sums formed on the host with the exact van Genuchten law;
// at dp = 0 the pass-free start (newtonResidualAtZero) gives what the pass
// gives.
#include <mpm_pressure_newton.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_test_backends.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( PressureNewton );

namespace ph = mpm::physics;

constexpr int nx = 3, ny = 3;
constexpr double h = 0.5, dt = 0.005, vol = 0.0625, n_p = 0.3;

ph::RetentionParams vanGenuchten()
{
    ph::RetentionParams r;
    r.model = ph::RetentionModel::VanGenuchten;
    r.alpha_per_pa = 4.4e-4;
    r.n_vg = 3.04;
    r.s_res = 0.23;
    return r;
}

// Two points in each of the cells (0, 0), (1, 0), (0, 1), (1, 1), far in
// suction to saturated.
struct Points
{
    std::vector<double> x, y, p_w;
    Points()
    {
        const double pressures[8] = { -30.0e3, -2.0e3, -800.0, -50.0,
                                      1.0e3,   -1.0e3, 2.0e3,  -5.0e3 };
        for ( int k = 0; k < 8; ++k )
        {
            const int cell = k / 2, ci = cell % 2, cj = cell / 2;
            x.push_back( ( ci + 0.3 + 0.4 * ( k % 2 ) ) * h );
            y.push_back( ( cj + 0.25 + 0.5 * ( k % 2 ) ) * h );
            p_w.push_back( pressures[k] );
        }
    }
};

// The stencil among the unknown cells: a link of weight w between any two
// neighbours (faces and corners); K's diagonal the sum of its links.
double linkWeight( const int c, const int k )
{
    return 1.0e-9 * ( 1.0 + 0.25 * ( ( 3 * c + k ) % 5 ) );
}

bool isUnknown( const int i, const int j )
{
    return i >= 0 && i < 2 && j >= 0 && j < 2;
}

template <class ExecSpace>
struct NewtonProblem
{
    using cell_view = Kokkos::View<double**, mpm::DeviceType<ExecSpace>>;
    Points cloud;
    ph::GridGeometry grid;
    ph::MaterialTable materials;
    ph::WaterParams water;
    mpm::ParticleViews<ExecSpace> points;
    mpm::WaterParticleViews<ExecSpace> water_points;
    mpm::PressurePointTerms<ExecSpace> terms;
    mpm::NodeStencilSystem<ExecSpace> system;
    mpm::NewtonSums<ExecSpace> sums;
    cell_view b, k_diagonal, dp, residual;

    NewtonProblem()
        : points( 8 )
        , water_points( 8 )
        , system( nx - 1, ny - 1, nx * ny )
        , sums( "newton_sums", nx * ny )
        , b( "b", nx, ny )
        , k_diagonal( "k_diagonal", nx, ny )
        , dp( "dp", nx, ny )
        , residual( "residual", nx, ny )
    {
        grid.h = h;
        grid.nx = nx;
        grid.ny = ny;
        materials.materials[0].retention = vanGenuchten();
        materials.size = 1;
        terms = mpm::PressurePointTerms<ExecSpace>( grid );

        auto x_h = Kokkos::create_mirror_view( points.x_p );
        auto p_h = Kokkos::create_mirror_view( water_points.p_w_p );
        auto S_h = Kokkos::create_mirror_view( water_points.S_p );
        auto dS_h = Kokkos::create_mirror_view( water_points.dS_dp_p );
        for ( int p = 0; p < 8; ++p )
        {
            x_h( p, 0 ) = cloud.x[p];
            x_h( p, 1 ) = cloud.y[p];
            p_h( p ) = cloud.p_w[p];
            const ph::RetentionState state =
                ph::Retention{}( vanGenuchten(), cloud.p_w[p] );
            S_h( p ) = state.S;
            dS_h( p ) = state.dS_dp;
        }
        Kokkos::deep_copy( points.x_p, x_h );
        Kokkos::deep_copy( water_points.p_w_p, p_h );
        Kokkos::deep_copy( water_points.S_p, S_h );
        Kokkos::deep_copy( water_points.dS_dp_p, dS_h );
        Kokkos::deep_copy( points.status_p, mpm::point_active );
        Kokkos::deep_copy( points.m_p, 100.0 );
        Kokkos::deep_copy( points.vol_p, vol );
        Kokkos::deep_copy( water_points.n_p, n_p );
        Kokkos::deep_copy( water_points.k_rel_p, 1.0 );
        Kokkos::deep_copy( water_points.p_w_condition_p, -1 );

        // The point terms at rest (storage_c, free_c); then the operator.
        mpm::GridViews<ExecSpace> nodes( grid );
        mpm::WaterGridViews<ExecSpace> water_nodes( grid );
        const auto no_source = KOKKOS_LAMBDA( const int ) { return 0.0; };
        mpm::CellPointLists<ExecSpace> lists( points.size(), nx * ny );
        mpm::pressurePointTerms( ExecSpace(), points, water_points, nodes,
                                 water_nodes, water, no_source, lists, terms );

        auto a_h = Kokkos::create_mirror_view( system.a );
        auto nodes_h = Kokkos::create_mirror_view( system.nodes );
        auto b_h = Kokkos::create_mirror_view( b );
        auto k_h = Kokkos::create_mirror_view( k_diagonal );
        Kokkos::deep_copy( a_h, 0.0 );
        int m = 0;
        for ( int i = 0; i < nx; ++i )
            for ( int j = 0; j < ny; ++j )
            {
                if ( !isUnknown( i, j ) )
                    continue;
                nodes_h( m++ ) = i * ny + j;
                for ( int k = 0; k < 9; ++k )
                {
                    const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                    if ( k == 4 || !isUnknown( ii, jj ) )
                        continue;
                    // Symmetric: the link's weight from its lower end.
                    const int c = std::min( i * ny + j, ii * ny + jj );
                    const double w = linkWeight( c, std::min( k, 8 - k ) );
                    a_h( i, j, k ) = -w;
                    k_h( i, j ) += w;
                }
                a_h( i, j, 4 ) = 7.0; // what a step left there: not read
                b_h( i, j ) = 1.0e-6 * ( 1.0 + i + 2 * j );
            }
        system.num_nodes = m;
        Kokkos::deep_copy( system.a, a_h );
        Kokkos::deep_copy( system.nodes, nodes_h );
        Kokkos::deep_copy( b, b_h );
        Kokkos::deep_copy( k_diagonal, k_h );
    }

    // newtonStorageSums and newtonResidual at dp (cell values); |R|^2.
    double residualAt( const double increments[nx][ny] )
    {
        auto dp_h = Kokkos::create_mirror_view( dp );
        for ( int i = 0; i < nx; ++i )
            for ( int j = 0; j < ny; ++j )
                dp_h( i, j ) = isUnknown( i, j ) ? increments[i][j] : 0.0;
        Kokkos::deep_copy( dp, dp_h );
        mpm::newtonStorageSums( ExecSpace(), points, water_points, materials,
                                water, false, grid, terms, dp, dt, sums );
        return mpm::newtonResidual( ExecSpace(), sums, b, k_diagonal, dp,
                                    residual, system );
    }

    // R and A's diagonal at the unknowns, on the host.
    void read( std::vector<double>& r, std::vector<double>& diagonal ) const
    {
        const auto r_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), residual );
        const auto a_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), system.a );
        r.clear();
        diagonal.clear();
        for ( int i = 0; i < 2; ++i )
            for ( int j = 0; j < 2; ++j )
            {
                r.push_back( r_h( i, j ) );
                diagonal.push_back( a_h( i, j, 4 ) );
            }
    }
};

TYPED_TEST( PressureNewton, residual_matches_the_host_sums )
{
    NewtonProblem<TypeParam> problem;
    const double increments[nx][ny] = {
        { 800.0, -300.0, 0.0 }, { 5.0e3, -2.5e3, 0.0 }, { 0.0, 0.0, 0.0 } };
    const double rr = problem.residualAt( increments );
    std::vector<double> r, diagonal;
    problem.read( r, diagonal );

    // The host: each point's exact stored water and tangent at p_w + dp.
    const auto a_h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                          problem.system.a );
    const auto k_h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                          problem.k_diagonal );
    const double K_w = problem.water.bulk_modulus;
    double expected_rr = 0.0;
    int u = 0;
    for ( int i = 0; i < 2; ++i )
        for ( int j = 0; j < 2; ++j, ++u )
        {
            double stored = 0.0, tangent = 0.0;
            for ( int p = 0; p < 8; ++p )
            {
                if ( int( problem.cloud.x[p] / h ) != i ||
                     int( problem.cloud.y[p] / h ) != j )
                    continue;
                const double p_w = problem.cloud.p_w[p];
                const ph::RetentionState before =
                    ph::Retention{}( vanGenuchten(), p_w );
                const ph::RetentionState after =
                    ph::Retention{}( vanGenuchten(), p_w + increments[i][j] );
                stored += vol *
                          ( n_p * ( after.S - before.S ) +
                            n_p * before.S * increments[i][j] / K_w ) /
                          dt;
                tangent +=
                    vol * ( n_p * after.dS_dp + n_p * after.S / K_w ) / dt;
            }
            double k_dp = k_h( i, j ) * increments[i][j];
            for ( int k = 0; k < 9; ++k )
            {
                const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                if ( k != 4 && isUnknown( ii, jj ) )
                    k_dp += a_h( i, j, k ) * increments[ii][jj];
            }
            const double b = 1.0e-6 * ( 1.0 + i + 2 * j );
            const double expected = b - stored - k_dp;
            EXPECT_NEAR( r[u], expected, 1e-10 * std::abs( stored ) + 1e-18 )
                << "cell " << i << ", " << j;
            EXPECT_NEAR( diagonal[u], k_h( i, j ) + tangent, 1e-10 * tangent );
            expected_rr += expected * expected;
        }
    EXPECT_NEAR( rr, expected_rr, 1e-9 * expected_rr );
}

TYPED_TEST( PressureNewton, start_at_zero_needs_no_pass_over_the_points )
{
    NewtonProblem<TypeParam> problem;
    const double zero[nx][ny] = {};
    const double rr = problem.residualAt( zero );
    std::vector<double> r, diagonal;
    problem.read( r, diagonal );

    const double rr_at_zero = mpm::newtonResidualAtZero(
        TypeParam(), problem.b, problem.terms.storage_c, problem.k_diagonal, dt,
        problem.dp, problem.residual, problem.system );
    std::vector<double> r_zero, diagonal_zero;
    problem.read( r_zero, diagonal_zero );
    EXPECT_DOUBLE_EQ( rr_at_zero, rr );
    for ( int u = 0; u < 4; ++u )
    {
        EXPECT_DOUBLE_EQ( r_zero[u], r[u] );
        EXPECT_NEAR( diagonal_zero[u], diagonal[u], 1e-12 * diagonal[u] );
    }
}

} // namespace
