#include <mpm_pressure_operator.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_pressure_terms.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
MPM_TEST_BACKEND_SUITE( PressureOperator );

// A 4 x 4 block of cells of 0.5 m (cells 1..4) on a 6 x 6 grid, 2 x 2
// points per cell at the Gauss positions, every node of mobility mu along x
// and y. Each cell's gradient sums are V grad N integrated exactly, +-h/2
// per component, so K = G^T mu G has 2 tau at a cell and -tau/2 at its
// diagonal neighbours (tau = mu h^2) and nothing at its face neighbours:
// the checkerboard is in its null space. With the checkerboard penalty a
// cell inside the block has the 5-point stencil (4 tau, faces -tau); a cell
// on the block's left edge (its left neighbours empty: a free surface)
// keeps only the penalty of its two inner corner nodes: 3 tau, -tau to the
// right, -tau/2 above and below, 0 at the corners; the operator is
// symmetric, and a cell whose neighbours are all unknowns loses no water
// (its row sums to 0).
TYPED_TEST( PressureOperator, gauss_points_give_the_five_point_stencil )
{
    using exec_space = TypeParam;
    const double h = 0.5, mobility = 2.0e-6;
    const int cells = 4;
    mpm::physics::GridGeometry grid;
    grid.h = h;
    grid.nx = grid.ny = 6;
    const int num_points = 4 * cells * cells;
    mpm::ParticleViews<exec_space> points( num_points );
    mpm::WaterParticleViews<exec_space> water_points( num_points );
    mpm::GridViews<exec_space> nodes( grid );
    mpm::WaterGridViews<exec_space> water_nodes( grid );
    auto x_h = Kokkos::create_mirror_view( points.x_p );
    const double g = 0.5 / std::sqrt( 3.0 );
    int p = 0;
    for ( int ci = 1; ci <= cells; ++ci )
        for ( int cj = 1; cj <= cells; ++cj )
            for ( int q = 0; q < 4; ++q, ++p )
            {
                x_h( p, 0 ) = ( ci + 0.5 + ( q % 2 ? g : -g ) ) * h;
                x_h( p, 1 ) = ( cj + 0.5 + ( q / 2 ? g : -g ) ) * h;
            }
    Kokkos::deep_copy( points.x_p, x_h );
    Kokkos::deep_copy( points.vol_p, 0.25 * h * h );
    Kokkos::deep_copy( points.status_p, mpm::point_active );
    Kokkos::deep_copy( water_points.n_p, 0.3 );
    Kokkos::deep_copy( water_points.S_p, 1.0 );
    Kokkos::deep_copy( water_points.p_w_condition_p, -1 );

    const auto terms = mpm_test::pressureTermsWithoutSource(
        grid, points, water_points, nodes, water_nodes );
    auto g_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), terms.g_c );
    for ( int k = 0; k < 4; ++k )
    {
        EXPECT_NEAR( g_h( 2, 3, 2 * k ), ( k % 2 ? 0.5 : -0.5 ) * h, 1e-12 );
        EXPECT_NEAR( g_h( 2, 3, 2 * k + 1 ), ( k / 2 ? 0.5 : -0.5 ) * h,
                     1e-12 );
    }

    Kokkos::View<double** [2], mpm::DeviceType<exec_space>> mu_i(
        "mu", grid.nx + 1, grid.ny + 1 );
    Kokkos::deep_copy( mu_i, mobility );
    mpm::NodeStencilSystem<exec_space> system( grid.nx - 1, grid.ny - 1,
                                               grid.nx * grid.ny );
    mpm::assemblePressureOperator( exec_space(), grid, terms, mu_i, system );
    EXPECT_EQ( system.num_nodes, cells * cells );
    auto a =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), system.a );
    const double tau = mobility * h * h;
    for ( int i = 1; i <= cells; ++i )
        for ( int j = 1; j <= cells; ++j )
        {
            double row = 0.0;
            for ( int k = 0; k < 9; ++k )
            {
                row += a( i, j, k );
                const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                EXPECT_NEAR( a( i, j, k ), a( ii, jj, 8 - k ), 1e-12 * tau )
                    << i << " " << j << " " << k;
            }
            if ( i > 1 && i < cells && j > 1 && j < cells )
            {
                EXPECT_NEAR( row, 0.0, 1e-12 * tau ) << i << " " << j;
            }
        }
    for ( int k = 0; k < 9; ++k )
    {
        const double inner = k == 4 ? 4.0 : k % 2 == 1 ? -1.0 : 0.0;
        EXPECT_NEAR( a( 3, 3, k ), inner * tau, 1e-12 * tau ) << k;
    }
    // Cell (1, 2): k = 3 (di + 1) + (dj + 1).
    const double edge[9] = { 0.0, 0.0, 0.0, -0.5, 3.0, -0.5, 0.0, -1.0, 0.0 };
    for ( int k = 0; k < 9; ++k )
        EXPECT_NEAR( a( 1, 2, k ), edge[k] * tau, 1e-12 * tau ) << k;
}

} // namespace
