#ifndef MPM_HOST_SNAPSHOT_HPP
#define MPM_HOST_SNAPSHOT_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <records/mpm_point_fields.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
//! Copies a View into a host vector (point-major).
template <class View, class T>
void copyToHost( const View& view, std::vector<T>& out )
{
    const auto h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
    out.assign( h.data(), h.data() + h.span() );
}

//---------------------------------------------------------------------------//
//! Host copy of the output's point fields (pointFields, intPointFields) of
//! the points `pv`; the water fields only if `wv` is allocated.
template <class ExecSpace>
HostSnapshot hostSnapshot( const ParticleViews<ExecSpace>& pv,
                           const WaterParticleViews<ExecSpace>& wv )
{
    HostSnapshot snap;
    snap.num_points = pv.size();
    const auto take = [&]( const char* name, const auto& view )
    {
        using value_type =
            typename std::decay_t<decltype( view )>::non_const_value_type;
        if ( const auto member = snapshotMemberOf<value_type>( name ) )
            copyToHost( view, snap.*member );
    };
    forEachView( pv, take );
    if ( wv.allocated() )
        forEachView( wv, take );
    std::vector<double> x0;
    copyToHost( pv.x0_p, x0 );
    snap.displacement.resize( x0.size() );
    for ( std::size_t k = 0; k < x0.size(); ++k )
        snap.displacement[k] = snap.x[k] - x0[k];
    return snap;
}

} // namespace mpm

#endif // MPM_HOST_SNAPSHOT_HPP
