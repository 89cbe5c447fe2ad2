#ifndef MPM_TEST_FIXTURES_HPP
#define MPM_TEST_FIXTURES_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>

#include <Kokkos_Core.hpp>

#include <vector>

namespace mpm_test
{
//! A grid of nx x ny unit-free cells of size h at the origin.
inline mpm::physics::GridGeometry makeGrid( const int nx, const int ny,
                                            const double h )
{
    mpm::physics::GridGeometry grid;
    grid.x0 = 0.0;
    grid.y0 = 0.0;
    grid.h = h;
    grid.nx = nx;
    grid.ny = ny;
    return grid;
}

/*!
  \brief Points at the 2 x 2 Gauss positions of every cell of the block
  [ci0, ci1) x [cj0, cj1), with volume h^2 / 4 and density rho.
*/
template <class ExecSpace>
mpm::ParticleViews<ExecSpace>
gaussPoints( const mpm::physics::GridGeometry& grid, const int ci0,
             const int ci1, const int cj0, const int cj1, const double rho )
{
    const double g[2] = { 0.5 - 0.5 / std::sqrt( 3.0 ),
                          0.5 + 0.5 / std::sqrt( 3.0 ) };
    const int n = 4 * ( ci1 - ci0 ) * ( cj1 - cj0 );
    mpm::ParticleViews<ExecSpace> pv( n );
    auto x_h = Kokkos::create_mirror( pv.x_p );
    auto vol_h = Kokkos::create_mirror( pv.vol_p );
    auto m_h = Kokkos::create_mirror( pv.m_p );
    auto id_h = Kokkos::create_mirror( pv.id_p );
    int p = 0;
    for ( int cj = cj0; cj < cj1; ++cj )
        for ( int ci = ci0; ci < ci1; ++ci )
            for ( int b = 0; b < 2; ++b )
                for ( int a = 0; a < 2; ++a, ++p )
                {
                    x_h( p, 0 ) = grid.x0 + ( ci + g[a] ) * grid.h;
                    x_h( p, 1 ) = grid.y0 + ( cj + g[b] ) * grid.h;
                    vol_h( p ) = 0.25 * grid.h * grid.h;
                    m_h( p ) = rho * vol_h( p );
                    id_h( p ) = p;
                }
    // The current and the reference positions and volumes start equal.
    for ( const auto& view : { pv.x_p, pv.x0_p } )
        Kokkos::deep_copy( view, x_h );
    for ( const auto& view : { pv.vol_p, pv.vol0_p } )
        Kokkos::deep_copy( view, vol_h );
    Kokkos::deep_copy( pv.m_p, m_h );
    Kokkos::deep_copy( pv.id_p, id_h );
    Kokkos::deep_copy( pv.status_p, mpm::point_active );
    return pv;
}

} // namespace mpm_test

#endif // MPM_TEST_FIXTURES_HPP
