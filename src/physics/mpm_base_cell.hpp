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
  The empty part holds its own weight: its total stress and p_w are those
  of the soil's centre x_bar (the points' volume-weighted mean) growing
  with depth below it (weightGradients), f = f_bar + (x - x_bar) . grad f.
  With the first moments
    E_k[i][j] = int_(cell \ soil) (x_i - x_bar_i) dN_k/dx_j dA
  (missingMoments) the mixture force is -(sigma_bar . D + dsigma/dx_i . E[i])
  with the total (Bishop) stress and the water force (per unit water volume
  fraction, as the P2G's sum p_w V grad N) p_bar D + dp/dx_i E[i]. With the
  mean alone the cell's one pressure acted as that of the whole cell's
  centre: the points of a cell cut 0.73 up carried the pressure of 0.14 m
  below them (1.4 kPa in a wetted column). (Gradients from the neighbour
  cells' means instead made the cut cells' forces depend on their own
  pressure 1.4 to 2 times as strongly: a saturated layer on a staircase
  base went unstable at a Courant number of 0.9.) Its weight is W_k g,
  W_k = int_cell N_k - sum V_p N_k(x_p) (virtual) with the cell's density
  per volume, so a pressure varying with depth is in equilibrium there as
  in a full cell (without it the cut cells' pressures made up the missing
  weight and, at different heights along a staircase base, pushed the
  water sideways: a saturated layer on a 10-degree base circulated at
  0.3 m/s).
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

    /*!
      The first moments E_k[i][j] = int_(cell \ soil) (x_i - x_bar_i)
      dN_k/dx_j dA the corner misses, m^2, from the point sums M0, M_xi,
      M_eta, M_xi_eta, M_xi_xi = sum V_p xi_p^2 and M_eta_eta. With
      dN_k/dx = (2a - 1) B(eta) / h, B = b ? eta : 1 - eta (and dN_k/dy
      alike with A(xi)), over the cell int (xi - xi_bar) B = (1/2 - xi_bar)
      / 2, int (xi - xi_bar) A = (a ? 1/3 : 1/6) - xi_bar / 2, and over
      the points sum V_p (xi - xi_bar) B = (2b - 1) C, sum V_p (xi - xi_bar)
      A = (2a - 1) V_xi (C the covariance sum, V_xi the variance sum).
    */
    KOKKOS_INLINE_FUNCTION void
    missingMoments( const int k, const double m0, const double m_xi,
                    const double m_eta, const double m_xi_eta,
                    const double m_xi_xi, const double m_eta_eta,
                    double E[2][2] ) const
    {
        const int a = k & 1;
        const int b = k >> 1;
        const double s_a = 2 * a - 1;
        const double s_b = 2 * b - 1;
        const double xi = m_xi / m0;
        const double eta = m_eta / m0;
        const double covariance = m_xi_eta - xi * m_eta;
        const double variance_xi = m_xi_xi - xi * m_xi;
        const double variance_eta = m_eta_eta - eta * m_eta;
        const double h2 = h * h;
        E[0][0] = s_a * ( 0.25 * h2 * ( 1.0 - 2.0 * xi ) - s_b * covariance );
        E[0][1] = s_b * ( h2 * ( ( a ? 1.0 / 3.0 : 1.0 / 6.0 ) - 0.5 * xi ) -
                          s_a * variance_xi );
        E[1][0] = s_a * ( h2 * ( ( b ? 1.0 / 3.0 : 1.0 / 6.0 ) - 0.5 * eta ) -
                          s_b * variance_eta );
        E[1][1] = s_b * ( 0.25 * h2 * ( 1.0 - 2.0 * eta ) - s_a * covariance );
    }

    //! Gradients of the empty part's total stress (xx, yy, xy) and p_w.
    struct Gradients
    {
        double dsigma_dx[3]; //!< Pa/m
        double dsigma_dy[3]; //!< Pa/m
        double dp_w[2];      //!< Pa/m
    };

    /*!
      The empty part in equilibrium under its own weight (density rho, of
      the water rho_w): with d = g / |g| and the depth delta = d . (x -
      x_bar) below the soil's centre,
        sigma = sigma_bar - rho |g| delta (d d^T + K t t^T),
        p_w = p_bar + rho_w |g| delta,
      t normal to d and K the ratio of the cell's mean total stresses
      across and along d (in [0, 1]; 0 unless compressive along d), so that
      div sigma + rho g = 0 and grad p_w = rho_w g, and the stress across
      grows as the cell's ratio says (no shear).
    */
    KOKKOS_INLINE_FUNCTION static Gradients
    weightGradients( const double g[2], const double density,
                     const double water_density, const double sigma[3] )
    {
        Gradients out{ { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 }, { 0.0, 0.0 } };
        const double magnitude =
            Kokkos::Experimental::sqrt( g[0] * g[0] + g[1] * g[1] );
        if ( !( magnitude > 0.0 ) )
            return out;
        const double d[2] = { g[0] / magnitude, g[1] / magnitude };
        const double t[2] = { -d[1], d[0] };
        const auto normal = [&]( const double u[2] )
        {
            return sigma[0] * u[0] * u[0] + sigma[1] * u[1] * u[1] +
                   2.0 * sigma[2] * u[0] * u[1];
        };
        const double along = normal( d );
        double K = along < 0.0 ? normal( t ) / along : 0.0;
        K = K < 0.0 ? 0.0 : ( K > 1.0 ? 1.0 : K );
        const double A[3] = { d[0] * d[0] + K * t[0] * t[0],
                              d[1] * d[1] + K * t[1] * t[1],
                              d[0] * d[1] + K * t[0] * t[1] };
        for ( int c = 0; c < 3; ++c )
        {
            out.dsigma_dx[c] = -density * magnitude * A[c] * d[0];
            out.dsigma_dy[c] = -density * magnitude * A[c] * d[1];
        }
        out.dp_w[0] = water_density * g[0];
        out.dp_w[1] = water_density * g[1];
        return out;
    }

    /*!
      Mixture force on corner k, -int_(cell \ soil) sigma . grad N_k, from
      the total stress (xx, yy, xy) at the soil's centre and its
      derivatives along x and y (the same three components).
    */
    KOKKOS_INLINE_FUNCTION static void
    mixtureForce( const double D[2], const double E[2][2],
                  const double sigma[3], const double dsigma_dx[3],
                  const double dsigma_dy[3], double f[2] )
    {
        // Row j of the tensor (xx, xy; xy, yy) dotted with a vector v.
        const auto row = []( const double s[3], const int j, const double v0,
                             const double v1 )
        { return j == 0 ? s[0] * v0 + s[2] * v1 : s[2] * v0 + s[1] * v1; };
        for ( int j = 0; j < 2; ++j )
            f[j] = -( row( sigma, j, D[0], D[1] ) +
                      row( dsigma_dx, j, E[0][0], E[0][1] ) +
                      row( dsigma_dy, j, E[1][0], E[1][1] ) );
    }

    /*!
      Water force on corner k, int_(cell \ soil) p_w grad N_k, from p_w at
      the soil's centre and its gradient, Pa/m.
    */
    KOKKOS_INLINE_FUNCTION static void
    waterForce( const double D[2], const double E[2][2], const double p_w,
                const double grad[2], double f[2] )
    {
        for ( int j = 0; j < 2; ++j )
            f[j] = p_w * D[j] + grad[0] * E[0][j] + grad[1] * E[1][j];
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_BASE_CELL_HPP
