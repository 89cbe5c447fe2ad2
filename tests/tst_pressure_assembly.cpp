#include <mpm_pressure_assembly.hpp>
#include <mpm_test_backends.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
MPM_TEST_BACKEND_SUITE( PressureAssembly );

// A 4 x 4 block of cells of 0.5 m on a 6 x 6 grid, 2 x 2 points per cell at
// the Gauss positions (the 2-point rule integrates grad N_I . grad N_J
// exactly), mobility M and storage C. Hand-computed: the bilinear stencil
// of -lap, 8/3 at the node and -1/3 at each neighbour (independent of h),
// times Dt M, plus the lumped storage C h^2 / Dt at a node inside the
// block; every row of the flow part sums to 0 (a uniform pressure drives
// no flow); the operator is symmetric.
TYPED_TEST( PressureAssembly, gauss_points_give_the_bilinear_stencil )
{
    using exec_space = TypeParam;
    const double h = 0.5, dt = 0.1, mobility = 2.0e-6, storage = 1.0e-7;
    const int cells = 4;
    mpm::physics::GridGeometry grid;
    grid.h = h;
    grid.nx = grid.ny = 6;
    const int num_points = 4 * cells * cells;
    mpm::ParticleViews<exec_space> points( num_points );
    Kokkos::View<double*, mpm::DeviceType<exec_space>> m_p( "m", num_points ),
        c_p( "c", num_points );
    auto x_h = Kokkos::create_mirror_view( points.x_p );
    auto vol_h = Kokkos::create_mirror_view( points.vol_p );
    auto status_h = Kokkos::create_mirror_view( points.status_p );
    const double g = 0.5 / std::sqrt( 3.0 );
    int p = 0;
    for ( int ci = 1; ci <= cells; ++ci )
        for ( int cj = 1; cj <= cells; ++cj )
            for ( int q = 0; q < 4; ++q, ++p )
            {
                x_h( p, 0 ) = ( ci + 0.5 + ( q % 2 ? g : -g ) ) * h;
                x_h( p, 1 ) = ( cj + 0.5 + ( q / 2 ? g : -g ) ) * h;
                vol_h( p ) = 0.25 * h * h;
                status_h( p ) = mpm::point_active;
            }
    Kokkos::deep_copy( points.x_p, x_h );
    Kokkos::deep_copy( points.vol_p, vol_h );
    Kokkos::deep_copy( points.status_p, status_h );
    Kokkos::deep_copy( m_p, mobility );

    mpm::NodeStencilSystem<exec_space> system( grid.nx, grid.ny, 1 );
    mpm::PressureStencilSums<exec_space> sums( grid );
    // Storage off: the flow part alone.
    mpm::assemblePressureStencil( exec_space(), points, m_p, c_p, grid, dt,
                                  sums, system );
    auto a =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), system.a );
    const double unit = dt * mobility;
    for ( int i = 0; i <= grid.nx; ++i )
        for ( int j = 0; j <= grid.ny; ++j )
        {
            double row = 0.0;
            for ( int k = 0; k < 9; ++k )
            {
                row += a( i, j, k );
                const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                if ( ii < 0 || jj < 0 || ii > grid.nx || jj > grid.ny )
                    continue;
                EXPECT_NEAR( a( i, j, k ), a( ii, jj, 8 - k ), 1e-12 * unit )
                    << i << " " << j << " " << k;
            }
            EXPECT_NEAR( row, 0.0, 1e-12 * unit ) << i << " " << j;
        }
    // A node inside the block (2..4 in each direction).
    for ( int k = 0; k < 9; ++k )
        EXPECT_NEAR( a( 3, 3, k ), unit * ( k == 4 ? 8.0 / 3.0 : -1.0 / 3.0 ),
                     1e-12 * unit )
            << k;

    // With storage: the lumped C h^2 / Dt on the diagonal only.
    Kokkos::deep_copy( c_p, storage );
    mpm::assemblePressureStencil( exec_space(), points, m_p, c_p, grid, dt,
                                  sums, system );
    Kokkos::deep_copy( a, system.a );
    EXPECT_NEAR( a( 3, 3, 4 ), unit * 8.0 / 3.0 + storage * h * h / dt,
                 1e-12 * unit );
    EXPECT_NEAR( a( 3, 3, 0 ), -unit / 3.0, 1e-12 * unit );
    // A corner node of the block takes a quarter of a cell's storage.
    EXPECT_NEAR( a( 1, 1, 4 ), unit * 2.0 / 3.0 + 0.25 * storage * h * h / dt,
                 1e-12 * unit );
}

} // namespace
