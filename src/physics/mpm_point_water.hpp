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
  \brief Water volume rate of Eq. 8 at a point, 1/s:
  r = n S div v_w + (1 - n) S div v_s, with n S div v_w from the nodal
  relative flux (waterDivergenceAt), so that r = div q + S div v_s.
*/
KOKKOS_INLINE_FUNCTION double waterVolumeRate( const double n, const double S,
                                               const double div_v_w,
                                               const double L[2][2] )
{
    return n * S * div_v_w + ( 1.0 - n ) * S * ( L[0][0] + L[1][1] );
}

//! Eq. 2 over a step: (1 - n) V is constant, so the porosity after a
//! volume ratio J = V' / V is n' = 1 - (1 - n) / J.
KOKKOS_INLINE_FUNCTION double porosityAfterStep( const double n,
                                                 const double volume_ratio )
{
    return 1.0 - ( 1.0 - n ) / volume_ratio;
}

//! Eq. 8 source of an inflow, 1/s: the water volume the inflow adds per
//! unit initial point volume and time (`rate`), times the point's share
//! `weight`, per unit current volume, so that V source is the point's
//! share of the prescribed rain however its volume changed.
KOKKOS_INLINE_FUNCTION double inflowSource( const double rate,
                                            const double weight,
                                            const double vol0,
                                            const double vol )
{
    return rate * weight * vol0 / vol;
}

//! The pore pressure of a point after a step (PointPressureRule).
struct PointPressure
{
    double p_w;      //!< new pore pressure, Pa
    double p_w_free; //!< before a ponding cap, Pa
    bool capped;     //!< the ponding cap applied
};

/*!
  \brief The rules that give a point its new p_w (docs/formulation.md step
  6): from p_w the increment of Eq. 8, explicit when saturated,
  dp = volume_change K_w / n, else Newton's `dp`; a ponding inflow caps
  p_w at 0 (the excess runs off); a prescribed pressure replaces it all.
*/
KOKKOS_INLINE_FUNCTION PointPressure pointPressureAfterStep(
    const double p_w, const double dp, const double volume_change,
    const double n, const double bulk_modulus, const bool saturated,
    const bool ponding, const bool prescribed, const double p_w_prescribed )
{
    PointPressure result{ p_w, p_w, false };
    if ( saturated )
        result.p_w += volume_change * bulk_modulus / n;
    else if ( !prescribed )
        result.p_w += dp;
    result.p_w_free = result.p_w;
    result.capped = ponding && result.p_w > 0.0;
    if ( result.capped )
        result.p_w = 0.0;
    if ( prescribed )
        result.p_w = p_w_prescribed;
    return result;
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
