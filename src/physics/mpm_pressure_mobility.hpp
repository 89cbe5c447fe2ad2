#ifndef MPM_PRESSURE_MOBILITY_HPP
#define MPM_PRESSURE_MOBILITY_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//! How a pressure-gradient increment accelerates each phase, m^3/kg.
struct PressureMobility
{
    double water;   //!< Lambda_w: dv_w = -dt Lambda_w grad(dp)
    double solid;   //!< Lambda_s: dv_s = -dt Lambda_s grad(dp)
    double mixture; //!< M = n S Lambda_w + (1 - n) S Lambda_s
};

//---------------------------------------------------------------------------//
/*!
  \brief Mobilities of the semi-implicit pressure correction at a point
  (docs/formulation.md §9, item 2): the 2x2 drag solve of step 2 per unit
  volume,
    (a_w + Q) dv_w - Q dv_s = -dt n S grad(dp)
    -Q dv_w + (a_s + Q) dv_s = -dt (1 - n) S grad(dp)
  with a_w = f n S rho_w, a_s = f rho_s' (rho_s' = (1 - n) rho_s, the
  solid mass per unit mixture volume), Q = dt (n S)^2 mu / (k k_rel), so
    Lambda_w = ((a_s + Q) n S + Q (1 - n) S) / det,
    Lambda_s = (Q n S + (a_w + Q) (1 - n) S) / det,
    det = a_w a_s + Q (a_w + a_s).
  Drag-free (Q = 0): Lambda_w = 1 / (f rho_w), Lambda_s = S / (f rho_s);
  locked (Q infinite, k k_rel = 0): both S / (a_w + a_s), the mixture;
  no water (n S = 0): Lambda_w = 0, Lambda_s = S / (f rho_s).
*/
KOKKOS_INLINE_FUNCTION PressureMobility pressureMobility(
    const double n, const double S, const double solid_density_bulk,
    const double water_density, const double permeability, const double k_rel,
    const double viscosity, const double inertia_scaling, const double dt )
{
    const double nS = n * S;
    const double sS = ( 1.0 - n ) * S;
    const double a_w = inertia_scaling * nS * water_density;
    const double a_s = inertia_scaling * solid_density_bulk;
    const double mobility = permeability * k_rel;
    PressureMobility m;
    if ( !( mobility > 0.0 ) )
    {
        m.water = m.solid = S / ( a_w + a_s );
    }
    else
    {
        const double q = dt * nS * nS * viscosity / mobility;
        const double det = a_w * a_s + q * ( a_w + a_s );
        // No water (n S = 0): the solid alone.
        m.water = det > 0.0 ? ( ( a_s + q ) * nS + q * sS ) / det : 0.0;
        m.solid = det > 0.0 ? ( q * nS + ( a_w + q ) * sS ) / det : sS / a_s;
    }
    m.mixture = nS * m.water + sS * m.solid;
    return m;
}

//! Storage of Eq. 8, C = n dS/dp_w + n S / K_w (1/Pa): the water volume a
//! unit volume takes in per pascal at fixed skeleton volume.
KOKKOS_INLINE_FUNCTION double waterStorage( const double n, const double S,
                                            const double dS_dp,
                                            const double bulk_modulus )
{
    return n * dS_dp + n * S / bulk_modulus;
}

//! Eq. 8's stored water per unit volume gained from p_w to p_w + dp at a
//! fixed skeleton, n (S1 - S0) + n S0 dp / K_w (S0, S1 the saturations at
//! p_w and p_w + dp; as PorePressureNewton balances it).
KOKKOS_INLINE_FUNCTION double
storedWaterChange( const double n, const double S0, const double S1,
                   const double dp, const double bulk_modulus )
{
    return n * ( S1 - S0 ) + n * S0 * dp / bulk_modulus;
}

} // namespace physics
} // namespace mpm

#endif // MPM_PRESSURE_MOBILITY_HPP
