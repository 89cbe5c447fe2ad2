#include <mpm_pressure_correction.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_pressure_terms.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( PressureIncrementForces );

// The nodal forces of the cells' pressure increments from the cell sums
// g_c, g_S_c (pressureIncrementForces) against the point sums of step 1's
// form, summed here on the host: sum_p dp_c V grad N (water, per unit water
// fraction) and sum_p S dp_c V grad N (mixture) over the points with a free
// p_w. 13 points in 9 of the 16 cells of a 4 x 4 grid of 0.5 m cells
// (origin off zero), several per cell, different volumes and saturations,
// two of them prescribed (they take no increment); a cell with points but
// dp = 0 (not an unknown).
TYPED_TEST( PressureIncrementForces, cell_sums_give_the_point_sums )
{
    using exec_space = TypeParam;
    mpm::physics::GridGeometry grid;
    grid.x0 = -1.0;
    grid.y0 = 0.25;
    grid.h = 0.5;
    grid.nx = grid.ny = 4;
    const int num_points = 13;
    // Positions in cell units from the origin, volume, S, prescribed.
    const double gx[num_points] = { 0.3,  0.8, 0.55, 1.2, 1.7, 1.45, 2.1,
                                    2.95, 3.6, 0.4,  1.9, 2.5, 3.3 };
    const double gy[num_points] = { 0.2, 0.7,  0.45, 0.35, 0.9, 1.6, 1.1,
                                    1.8, 2.25, 3.7,  2.6,  3.4, 3.05 };
    const double vol[num_points] = { 0.06,  0.07,  0.05,  0.0625, 0.08,
                                     0.061, 0.059, 0.066, 0.07,   0.0625,
                                     0.064, 0.058, 0.067 };
    const double S[num_points] = { 1.0,  0.9,  0.75, 0.6, 1.0,  0.95, 0.4,
                                   0.85, 0.55, 1.0,  0.7, 0.65, 0.8 };
    const int condition[num_points] = { -1, -1, 0,  -1, -1, -1, -1,
                                        -1, -1, -1, 1,  -1, -1 };

    mpm::ParticleViews<exec_space> points( num_points );
    mpm::WaterParticleViews<exec_space> water_points( num_points );
    mpm::GridViews<exec_space> nodes( grid );
    mpm::WaterGridViews<exec_space> water_nodes( grid );
    Kokkos::deep_copy( points.status_p, mpm::point_active );
    Kokkos::deep_copy( points.m_p, 100.0 );
    Kokkos::deep_copy( water_points.n_p, 0.3 );
    Kokkos::deep_copy( nodes.m_i, 50.0 );
    Kokkos::deep_copy( water_nodes.m_w_i, 10.0 );
    Kokkos::deep_copy( water_nodes.vol_i, 0.03 );
    Kokkos::deep_copy( water_nodes.nS_i, 10.0 / ( 1000.0 * 0.03 ) );
    auto x_h = Kokkos::create_mirror_view( points.x_p );
    for ( int p = 0; p < num_points; ++p )
    {
        x_h( p, 0 ) = grid.x0 + gx[p] * grid.h;
        x_h( p, 1 ) = grid.y0 + gy[p] * grid.h;
    }
    Kokkos::deep_copy( points.x_p, x_h );
    mpm_test::setPointWater( points, water_points, num_points, vol, S,
                             condition );

    const auto terms = mpm_test::pressureTermsWithoutSource(
        grid, points, water_points, nodes, water_nodes );

    // Increments of the cells, Pa; cell (1, 3) holds point 10 but is no
    // unknown (dp = 0).
    Kokkos::View<double**, mpm::DeviceType<exec_space>> dp_c( "dp_c", grid.nx,
                                                              grid.ny );
    auto dp_h = Kokkos::create_mirror_view( dp_c );
    for ( int i = 0; i < grid.nx; ++i )
        for ( int j = 0; j < grid.ny; ++j )
            dp_h( i, j ) =
                ( i == 1 && j == 3 ) ? 0.0 : 100.0 * ( 1 + i - 2 * j );
    Kokkos::deep_copy( dp_c, dp_h );

    const int nx1 = grid.nx + 1, ny1 = grid.ny + 1;
    Kokkos::View<double** [4], mpm::DeviceType<exec_space>> forces( "forces",
                                                                    nx1, ny1 );
    const auto g = terms.g_c;
    const auto g_S = terms.g_S_c;
    const int nx = grid.nx, ny = grid.ny;
    Kokkos::parallel_for(
        Kokkos::RangePolicy<exec_space>( 0, nx1 * ny1 ),
        KOKKOS_LAMBDA( const int n ) {
            const int i = n / ny1, j = n % ny1;
            double f_w[2], f_m[2];
            mpm::pressureIncrementForces( i, j, nx, ny, dp_c, g, g_S, f_w,
                                          f_m );
            for ( int d = 0; d < 2; ++d )
            {
                forces( i, j, d ) = f_w[d];
                forces( i, j, 2 + d ) = f_m[d];
            }
        } );
    const auto forces_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), forces );

    // The point sums.
    std::vector<double> expected( nx1 * ny1 * 4, 0.0 );
    for ( int p = 0; p < num_points; ++p )
    {
        if ( condition[p] >= 0 )
            continue;
        const int ci = static_cast<int>( gx[p] ),
                  cj = static_cast<int>( gy[p] );
        const double xi = gx[p] - ci, eta = gy[p] - cj;
        const double water = dp_h( ci, cj ) * vol[p];
        for ( int b = 0; b < 2; ++b )
            for ( int a = 0; a < 2; ++a )
            {
                const double dNdx =
                    ( a ? 1.0 : -1.0 ) / grid.h * ( b ? eta : 1.0 - eta );
                const double dNdy =
                    ( a ? xi : 1.0 - xi ) * ( b ? 1.0 : -1.0 ) / grid.h;
                double* f = &expected[4 * ( ( ci + a ) * ny1 + cj + b )];
                f[0] += water * dNdx;
                f[1] += water * dNdy;
                f[2] += S[p] * water * dNdx;
                f[3] += S[p] * water * dNdy;
            }
    }
    double largest = 0.0;
    for ( const double f : expected )
        largest = std::max( largest, std::abs( f ) );
    ASSERT_GT( largest, 10.0 );
    for ( int i = 0; i < nx1; ++i )
        for ( int j = 0; j < ny1; ++j )
            for ( int f = 0; f < 4; ++f )
                EXPECT_NEAR( forces_h( i, j, f ),
                             expected[4 * ( i * ny1 + j ) + f],
                             1e-12 * largest )
                    << "node (" << i << ", " << j << "), field " << f;
}

} // namespace
