#ifndef MPM_NODAL_WATER_HPP
#define MPM_NODAL_WATER_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//! A node has water if it carries more than this fraction of its solid
//! mass (below it, its water moves with the solid).
constexpr double water_mass_fraction_floor = 1.0e-12;

//! True if a node of solid mass m_s and water mass m_w has water.
KOKKOS_INLINE_FUNCTION bool hasWater( const double m_w, const double m_s )
{
    return m_w > water_mass_fraction_floor * m_s;
}

//---------------------------------------------------------------------------//
/*!
  \brief Seepage velocity w = v_w - v_s (m/s) that carries a prescribed
  inward water flux q (m/s, per unit area) into a node of water mass m_w,
  solid mass m_s and mixture volume vol: the node's water volume fraction
  n S = m_w / (rho_w vol) moves at w with n S w = q, so w = q rho_w vol /
  m_w. Zero without water.
*/
KOKKOS_INLINE_FUNCTION double tiedSeepage( const double q, const double m_w,
                                           const double m_s, const double vol,
                                           const double water_density )
{
    return hasWater( m_w, m_s ) ? q * water_density * vol / m_w : 0.0;
}

//---------------------------------------------------------------------------//
/*!
  \brief Nodal drag coefficient of Eq. 9 (kg/s) from nodal quantities:
  Q = (n S)^2 mu V / k_bar with the nodal mean permeability
  k_bar = sum N k k_rel V / sum N V. Averaging permeabilities (not the
  resistances mu / (k k_rel)) lets water enter a dry neighbour at a wetting
  front, where k_rel drops by ten orders of magnitude between two points.
*/
KOKKOS_INLINE_FUNCTION double nodalDrag( const double nS,
                                         const double viscosity,
                                         const double volume,
                                         const double permeability_volume )
{
    return nS * nS * viscosity * volume * volume / permeability_volume;
}

//! Water volume fraction n S = m_w / (rho_w V) of a node of water mass m_w
//! (kg) and volume vol (m^3).
KOKKOS_INLINE_FUNCTION double waterFraction( const double m_w, const double vol,
                                             const double water_density )
{
    return m_w / ( water_density * vol );
}

//! The water state of a node for its momentum balance (Eqs. 9-10).
struct NodalWater
{
    double nS;   //!< water volume fraction n S = m_w / (rho_w V)
    bool locked; //!< no permeability: the water moves with the solid
    double drag; //!< drag coefficient Q, kg/s (nodalDrag; 0 if locked)
};

//! NodalWater of a node of water fraction nS (waterFraction), volume vol
//! (m^3) and permeability sum q = sum N k k_rel V (m^4).
KOKKOS_INLINE_FUNCTION NodalWater nodalWater( const double nS, const double vol,
                                              const double q,
                                              const double viscosity )
{
    // Zero permeability (k_rel = 0) locks the water to the solid.
    const bool locked = !( q > 0.0 );
    return { nS, locked, locked ? 0.0 : nodalDrag( nS, viscosity, vol, q ) };
}

/*!
  \brief Remapped (MUSL) water velocity of one component of a node: the
  solid's v_s where the node has no water, v_s plus the tied seepage
  (tiedSeepage of the prescribed flux q) on an impermeable or flux
  boundary, else the remapped momentum over the water mass.
*/
KOKKOS_INLINE_FUNCTION double
remappedWaterVelocity( const double v_s, const double mv_w, const double m_w,
                       const double m_s, const bool tied, const double q,
                       const double vol, const double water_density )
{
    if ( !hasWater( m_w, m_s ) )
        return v_s;
    if ( tied )
        return v_s + tiedSeepage( q, m_w, m_s, vol, water_density );
    return mv_w / m_w;
}

} // namespace physics
} // namespace mpm

#endif // MPM_NODAL_WATER_HPP
