#ifndef MPM_TWO_PHASE_SCATTER_HPP
#define MPM_TWO_PHASE_SCATTER_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//! Eq. 11 (Bishop, chi = S), tension positive: the total stress
//! sigma = sigma' - S p_w m of the effective stress sigma' (xx, yy, xy).
KOKKOS_INLINE_FUNCTION void bishopTotalStress( const double sigma_eff[3],
                                               const double S, const double p_w,
                                               double sigma[3] )
{
    const double bishop = S * p_w;
    sigma[0] = sigma_eff[0] - bishop;
    sigma[1] = sigma_eff[1] - bishop;
    sigma[2] = sigma_eff[2];
}

//! What one point carries to its nodes in the two-phase P2G (step 1).
struct TwoPhasePoint
{
    double m_s;                 //!< solid mass, kg
    double m_w;                 //!< water mass n S rho_w V, kg
    double vol;                 //!< volume V, m^3
    double permeability_volume; //!< k k_rel V, m^4
    double sigma[3];            //!< total stress (Eq. 11), Pa
    double p_w;                 //!< pore pressure, Pa
    double v_s[2], v_w[2];      //!< velocities, m/s
    double f_m[2];              //!< mixture weight and loads, N
    double water_density;       //!< rho_w, kg/m^3
    double g[2];                //!< gravity, m/s^2
};

//! TwoPhasePoint of a point of volume vol, porosity n, saturation S,
//! pore pressure p_w, solid mass m_s, effective stress sigma_eff,
//! permeability k k_rel, under gravity g and a load (N).
KOKKOS_INLINE_FUNCTION TwoPhasePoint twoPhasePoint(
    const double vol, const double n, const double S, const double p_w,
    const double m_s, const double sigma_eff[3], const double k_k_rel,
    const double v_s[2], const double v_w[2], const double g[2],
    const double load[2], const double water_density )
{
    TwoPhasePoint point;
    point.m_s = m_s;
    point.m_w = n * S * water_density * vol;
    point.vol = vol;
    point.permeability_volume = k_k_rel * vol;
    bishopTotalStress( sigma_eff, S, p_w, point.sigma );
    point.p_w = p_w;
    point.water_density = water_density;
    for ( int d = 0; d < 2; ++d )
    {
        point.v_s[d] = v_s[d];
        point.v_w[d] = v_w[d];
        point.f_m[d] = ( m_s + point.m_w ) * g[d] + load[d];
        point.g[d] = g[d];
    }
    return point;
}

//! A point's share of the two-phase sums of one node.
struct TwoPhaseNodeShare
{
    double m_s, m_w, vol, permeability_volume; //!< kg, kg, m^3, m^4
    double mv_s[2], mv_w[2];                   //!< momenta, kg m/s
    double f_m[2]; //!< mixture force N F_m - V sigma . grad N, N
    double f_w[2]; //!< water force per unit n S, N f_w + p_w V grad N, N
};

/*!
  \brief The share of node I (weight N, gradient grad N) of a point
  (step 1): masses, volume and permeability sum weighted by N, momenta,
  the mixture force (Eq. 10: weight and loads, minus the divergence of the
  total stress) and the water force of Eq. 9 per unit water volume
  fraction, rho_w V g N + p_w V grad N (the exact integration by parts of
  -grad p_w; the grid update multiplies it by the nodal n S).
*/
KOKKOS_INLINE_FUNCTION TwoPhaseNodeShare twoPhaseNodeShare(
    const TwoPhasePoint& point, const double N, const double grad_N[2] )
{
    TwoPhaseNodeShare share;
    share.m_s = N * point.m_s;
    share.m_w = N * point.m_w;
    share.vol = N * point.vol;
    share.permeability_volume = N * point.permeability_volume;
    const double div_sigma[2] = {
        point.sigma[0] * grad_N[0] + point.sigma[2] * grad_N[1],
        point.sigma[2] * grad_N[0] + point.sigma[1] * grad_N[1] };
    for ( int d = 0; d < 2; ++d )
    {
        share.mv_s[d] = N * point.m_s * point.v_s[d];
        share.mv_w[d] = N * point.m_w * point.v_w[d];
        share.f_m[d] = N * point.f_m[d] - point.vol * div_sigma[d];
        share.f_w[d] = N * point.water_density * point.vol * point.g[d] +
                       point.p_w * point.vol * grad_N[d];
    }
    return share;
}

} // namespace physics
} // namespace mpm

#endif // MPM_TWO_PHASE_SCATTER_HPP
