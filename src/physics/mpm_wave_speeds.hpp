#ifndef MPM_WAVE_SPEEDS_HPP
#define MPM_WAVE_SPEEDS_HPP

#include <physics/mpm_material_params.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
//! P-wave speed sqrt(E_c / rho) of a dry point of mass m, volume vol and
//! initial volume vol0 (E_c at its volume, MaterialParams::modulusFactor),
//! m/s.
KOKKOS_INLINE_FUNCTION double waveSpeedDry( const MaterialParams& m,
                                            const double mass, const double vol,
                                            const double vol0 )
{
    const double rho = mass / vol;
    return Kokkos::Experimental::sqrt( m.constrainedModulus() *
                                       m.modulusFactor( vol, vol0 ) / rho );
}

//---------------------------------------------------------------------------//
/*!
  \brief Wave speeds of one point (docs/formulation.md, step 10), m/s: the
  undrained mixture wave sqrt((E_c + S^2 / (n (dS/dp + S/K_w))) / rho_m)
  and the pore-water wave sqrt(S / ((dS/dp + S/K_w) rho_w)); returns the
  larger.
*/
KOKKOS_INLINE_FUNCTION double
twoPhaseWaveSpeed( const double constrained_modulus, const double rho_m,
                   const double rho_w, const double n, const double S,
                   const double dS_dp, const double bulk_modulus )
{
    namespace KE = Kokkos::Experimental;
    const double compressibility = dS_dp + S / bulk_modulus;
    const double c_mixture = KE::sqrt(
        ( constrained_modulus + S * S / ( n * compressibility ) ) / rho_m );
    const double c_water = KE::sqrt( S / ( compressibility * rho_w ) );
    return c_mixture > c_water ? c_mixture : c_water;
}

//! Fastest wave of a two-phase point of solid mass `mass`, volume vol,
//! initial volume vol0, porosity n and saturation S > 0 (twoPhaseWaveSpeed
//! with the saturated fluid stiffness, dS/dp_w = 0: see
//! mpm::criticalTimeStepTwoPhase), m/s. With dS/dp_w = 0 the waves reduce to
//! sqrt((E_c + S K_w / n) / rho_m) and sqrt(K_w / rho_w): one root, the
//! larger square taken first (every point of every step takes it).
KOKKOS_INLINE_FUNCTION double
waveSpeedTwoPhase( const MaterialParams& m, const WaterParams& water,
                   const double mass, const double vol, const double vol0,
                   const double n, const double S )
{
    const double rho_m = mass / vol + n * S * water.density;
    const double c2_mixture =
        ( m.constrainedModulus() * m.modulusFactor( vol, vol0 ) +
          S * water.bulk_modulus / n ) /
        rho_m;
    const double c2_water = water.bulk_modulus / water.density;
    return Kokkos::Experimental::sqrt( c2_mixture > c2_water ? c2_mixture
                                                             : c2_water );
}

//! Stable step h / (c + |v|) of a point (Courant number 1), s.
KOKKOS_INLINE_FUNCTION double pointTimeStep( const double cell_size,
                                             const double c, const double v_x,
                                             const double v_y )
{
    const double speed = Kokkos::Experimental::sqrt( v_x * v_x + v_y * v_y );
    return cell_size / ( c + speed );
}

} // namespace physics
} // namespace mpm

#endif // MPM_WAVE_SPEEDS_HPP
