#ifndef MPM_DIAGNOSIS_HPP
#define MPM_DIAGNOSIS_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace mpm
{
//! Host copy of a View (a separate allocation on host backends too).
template <class ViewType>
auto hostCopy( const ViewType& view )
{
    return Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
}

//---------------------------------------------------------------------------//
//! Diagnosis of one point: id, position, velocity, stress (and pore
//! pressure in two-phase scenes), step and time.
template <class ExecSpace>
std::string describePoint( const ParticleViews<ExecSpace>& pv,
                           const WaterParticleViews<ExecSpace>& wv, const int p,
                           const std::string& what, const long step,
                           const double time )
{
    const auto x = hostCopy( pv.x_p );
    const auto v = hostCopy( pv.v_p );
    const auto s = hostCopy( pv.sigma_p );
    const auto vol = hostCopy( pv.vol_p );
    const auto id = hostCopy( pv.id_p );
    std::ostringstream msg;
    msg << "material point " << id( p ) << " " << what << "\n"
        << "  at step " << step << ", t = " << time << " s\n"
        << "  position (" << x( p, 0 ) << ", " << x( p, 1 ) << ") m\n"
        << "  velocity (" << v( p, 0 ) << ", " << v( p, 1 ) << ") m/s\n"
        << "  stress xx, yy, xy, zz (" << s( p, 0 ) << ", " << s( p, 1 ) << ", "
        << s( p, 2 ) << ", " << s( p, 3 ) << ") Pa\n"
        << "  volume " << vol( p ) << " m^3/m";
    if ( wv.allocated() )
    {
        const auto p_w = hostCopy( wv.p_w_p );
        const auto S = hostCopy( wv.S_p );
        const auto v_w = hostCopy( wv.v_w_p );
        msg << "\n  pore pressure " << p_w( p ) << " Pa, saturation " << S( p )
            << ", water velocity (" << v_w( p, 0 ) << ", " << v_w( p, 1 )
            << ") m/s";
    }
    return msg.str();
}

//! Whether every component of row p of a host tensor view is finite.
template <class HostView>
bool finiteRow( const HostView& v, const int p )
{
    for ( std::size_t c = 0; c < v.extent( 1 ); ++c )
        if ( !std::isfinite( v( p, c ) ) )
            return false;
    return true;
}

//! Which quantity of point p is unstable, with its value.
template <class ExecSpace>
std::string unstableQuantity( const ParticleViews<ExecSpace>& pv,
                              const WaterParticleViews<ExecSpace>& wv,
                              const int p, const double speed_limit,
                              const double speed_factor )
{
    const auto x = hostCopy( pv.x_p );
    const auto v = hostCopy( pv.v_p );
    const auto vol = hostCopy( pv.vol_p );
    std::ostringstream what;
    const double speed = std::hypot( v( p, 0 ), v( p, 1 ) );
    if ( !std::isfinite( x( p, 0 ) ) || !std::isfinite( x( p, 1 ) ) )
        what << "position is not finite";
    else if ( !std::isfinite( speed ) )
        what << "velocity is not finite";
    else if ( speed > speed_limit )
        what << "speed " << speed << " m/s exceeds " << speed_limit << " m/s ("
             << speed_factor << " x the largest wave speed)";
    else if ( !( vol( p ) > 0.0 ) || !std::isfinite( vol( p ) ) )
        what << "volume " << vol( p ) << " m^3/m is not positive and finite";
    else if ( wv.allocated() && !std::isfinite( hostCopy( wv.p_w_p )( p ) ) )
        what << "pore pressure is not finite";
    else if ( !finiteRow( hostCopy( pv.sigma_p ), p ) )
        what << "stress is not finite";
    else if ( !finiteRow( hostCopy( pv.eps_p ), p ) )
        what << "strain is not finite";
    else if ( !std::isfinite( hostCopy( pv.eps_p_bar_p )( p ) ) )
        what << "plastic shear strain (eps_p_bar) is not finite";
    else
        what << "water velocity is not finite";
    return what.str();
}

} // namespace mpm

#endif // MPM_DIAGNOSIS_HPP
