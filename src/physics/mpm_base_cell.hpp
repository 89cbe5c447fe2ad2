#ifndef MPM_BASE_CELL_HPP
#define MPM_BASE_CELL_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Completion of the stress divergence in a cell cut by a fixed base
  (a cell with fixed and free nodes, its soil above a base line that is not
  a grid line): -int_(cell \ soil) sigma_bar . grad N_I dA, the part of the
  cell between the soil and the fixed nodes, with the cell's mean stress.

  The fixed nodes hold the soil kinematically (its velocity vanishes at
  the fixed node row, not at the base line), but the point integral
  -sum V_p sigma_p . grad N_I covers only the soil: with half a cell of
  soil, equilibrium of the first free node needs twice the stress (a
  hydrostatic column on a base 0.36 cell above a node row had p_w and
  sigma' twice their weight in its bottom cell). With the missing part
  added, a uniform stress exerts no net force on a free node (the patch
  test holds), and the base's reaction goes to the fixed nodes.

  From the cell's sums M0 = sum V_p, M_xi = sum V_p xi_p, M_eta = sum V_p
  eta_p (local coordinates in [0, 1]), corner k = a + 2 b (a, b in {0, 1})
  misses D_k = int_cell grad N_k - sum V_p grad N_k(x_p):
    D_x = (2a - 1) (h/2 - (b ? M_eta : M0 - M_eta) / h)
    D_y = (2b - 1) (h/2 - (a ? M_xi : M0 - M_xi) / h).
  Mixture force -sigma_bar . D with the mean total (Bishop) stress; water
  force (per unit water volume fraction, as the P2G's sum p_w V grad N)
  +p_bar D. The empty part also weighs what the cell's soil weighs per
  volume: W_k g with W_k = int_cell N_k - sum V_p N_k(x_p) (virtual), so a
  pressure varying with depth is in equilibrium there as in a full cell
  (without it the cut cells' pressures had to make up the missing weight
  and, at different heights along a staircase base, pushed the water
  sideways: a saturated layer on a 10-degree base circulated at 0.3 m/s).
*/
struct BaseCellCompletion
{
    double h; //!< cell size, m

    //! The area integral a corner misses (per unit thickness), m.
    KOKKOS_INLINE_FUNCTION void missing( const int k, const double m0,
                                         const double m_xi, const double m_eta,
                                         double D[2] ) const
    {
        const int a = k & 1;
        const int b = k >> 1;
        const double half = 0.5 * h;
        D[0] = ( 2 * a - 1 ) * ( half - ( b ? m_eta : m0 - m_eta ) / h );
        D[1] = ( 2 * b - 1 ) * ( half - ( a ? m_xi : m0 - m_xi ) / h );
    }

    /*!
      The volume integral of N_k the corner misses, m^2: h^2/4 - sum V_p
      N_k(x_p), from M0, M_xi, M_eta and M_xi_eta = sum V_p xi_p eta_p.
    */
    KOKKOS_INLINE_FUNCTION double missingVolume( const int k, const double m0,
                                                 const double m_xi,
                                                 const double m_eta,
                                                 const double m_xi_eta ) const
    {
        const int a = k & 1;
        const int b = k >> 1;
        // N_k = (a ? xi : 1 - xi) (b ? eta : 1 - eta), summed with V_p.
        double sum = m_xi_eta;
        if ( !a && !b )
            sum = m0 - m_xi - m_eta + m_xi_eta;
        else if ( !b )
            sum = m_xi - m_xi_eta;
        else if ( !a )
            sum = m_eta - m_xi_eta;
        return 0.25 * h * h - sum;
    }

    //! Mixture force on corner k from the mean total stress (xx, yy, xy).
    KOKKOS_INLINE_FUNCTION static void
    mixtureForce( const double D[2], const double sigma[3], double f[2] )
    {
        f[0] = -( sigma[0] * D[0] + sigma[2] * D[1] );
        f[1] = -( sigma[2] * D[0] + sigma[1] * D[1] );
    }

    //! Water force on corner k from the mean pore pressure.
    KOKKOS_INLINE_FUNCTION static void
    waterForce( const double D[2], const double p_w, double f[2] )
    {
        f[0] = p_w * D[0];
        f[1] = p_w * D[1];
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_BASE_CELL_HPP
