#ifndef MPM_HOST_TRANSFER_HPP
#define MPM_HOST_TRANSFER_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

#include <vector>

namespace mpm
{
//! Positions (x, y, x, y, ...) of the active points, on the host.
template <class ExecSpace>
std::vector<double> activePointPositions( const ParticleViews<ExecSpace>& pv )
{
    const auto x_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), pv.x_p );
    const auto status_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), pv.status_p );
    std::vector<double> x;
    for ( int p = 0; p < pv.size(); ++p )
        if ( status_h( p ) == point_active )
        {
            x.push_back( x_h( p, 0 ) );
            x.push_back( x_h( p, 1 ) );
        }
    return x;
}

//! Copies node flags, flat with index i (ny + 1) + j, into a (nx + 1) x
//! (ny + 1) View.
template <class IntView>
void copyNodeFlags( const physics::GridGeometry& grid,
                    const std::vector<int>& flags, const IntView& view )
{
    auto flags_h = Kokkos::create_mirror_view( view );
    const int ny1 = grid.ny + 1;
    for ( int i = 0; i <= grid.nx; ++i )
        for ( int j = 0; j < ny1; ++j )
            flags_h( i, j ) = flags[i * ny1 + j];
    Kokkos::deep_copy( view, flags_h );
}

} // namespace mpm

#endif // MPM_HOST_TRANSFER_HPP
