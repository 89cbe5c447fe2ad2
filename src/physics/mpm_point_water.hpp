#ifndef MPM_POINT_WATER_HPP
#define MPM_POINT_WATER_HPP

#include <physics/mpm_water_volumes.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//! Stored water of a point, V n S (1 + p_w / K_w), m^3/m (water at its
//! reference density; the compression p_w / K_w is Eq. 8's storage term).
KOKKOS_INLINE_FUNCTION double pointWaterVolume( const double volume,
                                                const double n, const double S,
                                                const double p_w,
                                                const double bulk_modulus )
{
    return volume * n * S * ( 1.0 + p_w / bulk_modulus );
}

/*!
  \brief Adds one point's step of Eq. 8 to `volumes`: the water its inflow
  adds (V dt source), the seepage the grid brings in (-V dt div q, where
  div q = r - S div v_s of the water volume rate r), and, where the update
  was overridden, what that took off or added.
  - Ponding capped an increment that would have reached p_w_free > 0: the
    water n S0/K_w p_w_free V above p_w = 0 runs off (S no longer grows
    above p_w = 0; `storage` is Eq. 8's n S0 / K_w).
  - A prescribed p_w: the water the point holds after the step,
    V (n (S - S0) + storage (p_w - p_w0)), less what Eq. 8 gave it,
    V volume_change (volume_change = dt (source - r)).
*/
KOKKOS_INLINE_FUNCTION void addPointStepWater(
    WaterStepVolumes& volumes, const double volume, const double dt,
    const double source, const double flux_divergence,
    const double volume_change, const double storage, const bool capped,
    const double p_w_free, const bool prescribed, const double n,
    const double S0, const double S, const double p_w0, const double p_w )
{
    volumes.point_inflow += volume * dt * source;
    volumes.flow_in -= volume * dt * flux_divergence;
    if ( prescribed )
        volumes.prescribed +=
            volume *
            ( n * ( S - S0 ) + storage * ( p_w - p_w0 ) - volume_change );
    else if ( capped )
        volumes.runoff += volume * storage * p_w_free;
}

} // namespace physics
} // namespace mpm

#endif // MPM_POINT_WATER_HPP
