#ifndef MPM_WATER_STORAGE_HPP
#define MPM_WATER_STORAGE_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
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

#endif // MPM_WATER_STORAGE_HPP
