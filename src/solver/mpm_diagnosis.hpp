#ifndef MPM_DIAGNOSIS_HPP
#define MPM_DIAGNOSIS_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <records/mpm_point_fields.hpp>
#include <solver/mpm_host_snapshot.hpp>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
//! The values of registry field `field` of point p in `snap`, or null if
//! the snapshot lacks the field (a water field in a dry scene).
inline const double* pointValues( const HostSnapshot& snap,
                                  const PointField& field, const int p )
{
    const std::vector<double>& values = snap.*field.values;
    return values.empty() ? nullptr : values.data() + p * field.components;
}

//! Whether every component of `field` of point p in `snap` is finite.
inline bool finiteField( const HostSnapshot& snap, const PointField& field,
                         const int p )
{
    const double* values = pointValues( snap, field, p );
    for ( int c = 0; values && c < field.components; ++c )
        if ( !std::isfinite( values[c] ) )
            return false;
    return true;
}

//---------------------------------------------------------------------------//
//! Diagnosis of one point: its id, step and time, and every field of the
//! point-field registry (water fields in two-phase scenes) with its unit.
template <class ExecSpace>
std::string describePoint( const ParticleViews<ExecSpace>& pv,
                           const WaterParticleViews<ExecSpace>& wv, const int p,
                           const std::string& what, const long step,
                           const double time )
{
    const HostSnapshot snap = hostSnapshot( pv, wv );
    std::ostringstream msg;
    msg << "material point " << snap.id[p] << " " << what << "\n"
        << "  at step " << step << ", t = " << time << " s";
    for ( const PointField& field : pointFields() )
    {
        const double* values = pointValues( snap, field, p );
        if ( !values )
            continue;
        const bool tensor = field.components == 4;
        msg << "\n  " << field.label << ( tensor ? " xx, yy, xy, zz " : " " )
            << ( field.components > 1 ? "(" : "" );
        for ( int c = 0; c < field.components; ++c )
            msg << ( c > 0 ? ", " : "" ) << values[c];
        msg << ( field.components > 1 ? ")" : "" );
        if ( std::strcmp( field.unit, "-" ) != 0 )
            msg << " " << field.unit;
    }
    return msg.str();
}

//---------------------------------------------------------------------------//
//! Which quantity of point p is unstable, with its value: the first field
//! of the registry that is not finite, else a speed above `speed_limit` or
//! a volume that is not positive.
template <class ExecSpace>
std::string unstableQuantity( const ParticleViews<ExecSpace>& pv,
                              const WaterParticleViews<ExecSpace>& wv,
                              const int p, const double speed_limit,
                              const double speed_factor )
{
    const HostSnapshot snap = hostSnapshot( pv, wv );
    std::ostringstream what;
    for ( const PointField& field : pointFields() )
        if ( !finiteField( snap, field, p ) )
        {
            what << field.label << " is not finite";
            return what.str();
        }
    const double speed = std::hypot( snap.v[2 * p], snap.v[2 * p + 1] );
    const double vol = snap.vol[p];
    if ( speed > speed_limit )
        what << "speed " << speed << " m/s exceeds " << speed_limit << " m/s ("
             << speed_factor << " x the largest wave speed)";
    else if ( !( vol > 0.0 ) )
        what << "volume " << vol << " m^3/m is not positive";
    else
        what << "no quantity is out of range on the host (the device check "
                "disagrees)";
    return what.str();
}

} // namespace mpm

#endif // MPM_DIAGNOSIS_HPP
