#ifndef MPM_TENSION_CUTOFF_HPP
#define MPM_TENSION_CUTOFF_HPP

#include <physics/mpm_material_params.hpp>
#include <physics/mpm_principal_return.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief Tensile strength of the cut-off, Pa: sigma_t = (sigma_t0 / c0) c,
  softened in proportion to the cohesion c(eps_p_bar) of Eqs. 14-15.

  Proportional softening keeps sigma_t below the apex c cot(phi) at every
  eps_p_bar (sigma_t0 < c0 cot(phi)), so the tension plane always cuts the
  Mohr-Coulomb pyramid and the return regions keep their layout; the
  residual tensile strength is sigma_t0 c_r / c0.
*/
KOKKOS_INLINE_FUNCTION double tensileStrength( const MaterialParams& m,
                                               const double c )
{
    return m.tensile_ratio * c;
}

//! A yield plane in principal stresses (sigma_1 >= sigma_2 >= sigma_3):
//! Mohr-Coulomb face f_ij (i major, j minor), or for j < 0 the Rankine
//! tension plane t_i: sigma_i - sigma_t = 0.
struct YieldPlane
{
    int i;
    int j;
};

//! Gradients a (of f) and b (of g), and r with a . sigma = r c on the plane.
KOKKOS_INLINE_FUNCTION void planeVectors( const MaterialParams& m,
                                          const YieldPlane& plane, double a[3],
                                          double b[3], double& r )
{
    if ( plane.j >= 0 )
    {
        faceGradient( plane.i, plane.j, m.sin_phi, a );
        faceGradient( plane.i, plane.j, m.sin_psi, b );
        r = 2.0 * m.cos_phi;
        return;
    }
    // Rankine plane: associated flow, a = b = e_i.
    for ( int k = 0; k < 3; ++k )
        a[k] = b[k] = k == plane.i ? 1.0 : 0.0;
    r = m.tensile_ratio;
}

//! Inverse of a 3x3 matrix by cofactors.
KOKKOS_INLINE_FUNCTION void invert3( const double a[3][3], double inv[3][3] )
{
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 3; ++j )
        {
            // Cofactor C_ji, cyclic indices.
            const int r0 = ( j + 1 ) % 3, r1 = ( j + 2 ) % 3;
            const int c0 = ( i + 1 ) % 3, c1 = ( i + 2 ) % 3;
            inv[i][j] = a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
        }
    const double det =
        a[0][0] * inv[0][0] + a[0][1] * inv[1][0] + a[0][2] * inv[2][0];
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 3; ++j )
            inv[i][j] /= det;
}

//---------------------------------------------------------------------------//
/*!
  \brief Exact return to n <= 3 planes active together (Clausen, Damkilde &
  Andersen 2007; de Souza Neto, Peric & Owen 2008, Sec. 8.2): sigma (Pa),
  the new eps_p_bar and the multipliers dgamma (m/m).

  sigma = sigma_tr - sum_k dgamma_k D b_k with D_ij = lambda + 2G delta_ij.
  Every plane reads a_k . sigma = r_k c (Mohr-Coulomb: r = 2 cos(phi);
  tension: r = sigma_t0 / c0), so the consistency conditions give
  dgamma(c) = A^-1 ( a . sigma_tr - c r ), A_kl = a_k . D b_l, affine in c,
  and the deviatoric plastic strain e(c) = dev( sum_k dgamma_k b_k ) too;
  the cohesion follows from softenedCohesion as for the faces alone.
*/
KOKKOS_INLINE_FUNCTION void
planeReturn( const MaterialParams& m, const int n, const YieldPlane planes[3],
             const double sigma_tr[3], const double eps_p_bar_n,
             double sigma[3], double& eps_p_bar, double dgamma[3] )
{
    const double two_g = 2.0 * m.shear_modulus;
    const double lambda = m.bulk_modulus - two_g / 3.0;

    // Gradients, flow directions b_k and D b_k; unused rows stay zero.
    double a[3][3] = {}, b[3][3] = {}, d_b[3][3] = {}, r[3] = {};
    for ( int k = 0; k < n; ++k )
    {
        planeVectors( m, planes[k], a[k], b[k], r[k] );
        const double lambda_tr = lambda * ( b[k][0] + b[k][1] + b[k][2] );
        for ( int i = 0; i < 3; ++i )
            d_b[k][i] = lambda_tr + two_g * b[k][i];
    }

    // A_kl = a_k . D b_l, padded with the identity beyond n.
    double mat[3][3] = {
        { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
    for ( int k = 0; k < n; ++k )
        for ( int l = 0; l < n; ++l )
            mat[k][l] =
                a[k][0] * d_b[l][0] + a[k][1] * d_b[l][1] + a[k][2] * d_b[l][2];
    double inv[3][3];
    invert3( mat, inv );

    // Affine multipliers dgamma(c) = gamma_u - c gamma_w.
    double a_sigma[3];
    for ( int k = 0; k < 3; ++k )
        a_sigma[k] = a[k][0] * sigma_tr[0] + a[k][1] * sigma_tr[1] +
                     a[k][2] * sigma_tr[2];
    double gamma_u[3], gamma_w[3];
    for ( int k = 0; k < 3; ++k )
    {
        gamma_u[k] = gamma_w[k] = 0.0;
        for ( int l = 0; l < 3; ++l )
        {
            gamma_u[k] += inv[k][l] * a_sigma[l];
            gamma_w[k] += inv[k][l] * r[l];
        }
    }

    // Deviatoric plastic strain e(c) = e_u - c e_w.
    double e_u[3] = { 0.0, 0.0, 0.0 }, e_w[3] = { 0.0, 0.0, 0.0 };
    for ( int k = 0; k < n; ++k )
    {
        const double mean = ( b[k][0] + b[k][1] + b[k][2] ) / 3.0;
        for ( int i = 0; i < 3; ++i )
        {
            e_u[i] += gamma_u[k] * ( b[k][i] - mean );
            e_w[i] += gamma_w[k] * ( b[k][i] - mean );
        }
    }

    // Cohesion, eps_p_bar; multipliers from c(eps_p_bar), so f = 0.
    double c = softenedCohesion( m, e_u, e_w, eps_p_bar_n );
    eps_p_bar = eps_p_bar_n + shearIncrement( m, e_u, e_w, c );
    c = cohesion( m, eps_p_bar );
    for ( int k = 0; k < 3; ++k )
        dgamma[k] = k < n ? gamma_u[k] - c * gamma_w[k] : 0.0;
    for ( int i = 0; i < 3; ++i )
    {
        sigma[i] = sigma_tr[i];
        for ( int k = 0; k < n; ++k )
            sigma[i] -= dgamma[k] * d_b[k][i];
    }
}

//---------------------------------------------------------------------------//
/*!
  \brief Largest violation (Pa) of the conditions a return must meet: order
  sigma_1 >= sigma_2 >= sigma_3, f_13 <= 0, sigma_1 <= sigma_t, and
  multipliers >= 0 (times 2G).

  The left tension corner is the point where f_13, f_23, t_1 and t_2 meet;
  its stress comes from (f_13, t_1, t_2) with multipliers (g_a, g_1, g_2),
  and its plastic strain must lie in the cone of all four flow directions
  (b_23 = b_13 - (1 + sin psi) (e_1 - e_2)): g_a >= 0, g_2 >= 0,
  g_1 + (1 + sin psi) g_a >= 0 and g_1 + g_2 >= 0.
*/
KOKKOS_INLINE_FUNCTION double violation( const MaterialParams& m,
                                         const ReturnRegion region, const int n,
                                         const double sigma[3],
                                         const double dgamma[3],
                                         const double eps_p_bar )
{
    namespace KE = Kokkos::Experimental;
    const double c = cohesion( m, eps_p_bar );
    double v = KE::fmax( sigma[1] - sigma[0], sigma[2] - sigma[1] );
    v = KE::fmax( v, yieldPrincipal( sigma, c, m.sin_phi, m.cos_phi ) );
    v = KE::fmax( v, sigma[0] - tensileStrength( m, c ) );
    double g[4] = { dgamma[0], dgamma[1], dgamma[2], 0.0 };
    int count = n;
    if ( region == ReturnRegion::LeftTensionCorner )
    {
        g[1] = dgamma[1] + ( 1.0 + m.sin_psi ) * dgamma[0];
        g[3] = dgamma[1] + dgamma[2];
        count = 4;
    }
    for ( int k = 0; k < count; ++k )
        v = KE::fmax( v, -2.0 * m.shear_modulus * g[k] );
    return v;
}

//---------------------------------------------------------------------------//
//! Whether a Mohr-Coulomb return (principal sigma) also meets the cut-off.
KOKKOS_INLINE_FUNCTION bool
belowCutoff( const MaterialParams& m, const ReturnRegion region,
             const double sigma_tr[3], const double c_n, const double sigma[3],
             const double eps_p_bar )
{
    namespace KE = Kokkos::Experimental;
    if ( region == ReturnRegion::Elastic || region == ReturnRegion::Apex )
        return false;
    const double tol =
        1e-12 * ( KE::fabs( sigma_tr[0] ) + KE::fabs( sigma_tr[2] ) + c_n );
    return sigma[0] <= tensileStrength( m, cohesion( m, eps_p_bar ) ) + tol;
}

//---------------------------------------------------------------------------//
/*!
  \brief Return with the tension plane active (Rankine cut-off sigma_1 <=
  sigma_t with the Mohr-Coulomb surface): sigma (Pa), eps_p_bar, region.

  Multisurface active-set return (Clausen, Damkilde & Andersen 2007): the
  sets of planes that can be active with t_1 are tried in turn, and the
  first whose exact return (planeReturn) meets every condition (violation
  <= round-off) is taken: tension plane, tension edge, tension apex, main
  plane with tension, right and left tension corners. Each set is solved
  exactly, so the accepted one satisfies consistency (active planes = 0 to
  round-off), admissibility and non-negative multipliers. Should no set
  pass (round-off at a region boundary), the least violating one is kept.
*/
KOKKOS_INLINE_FUNCTION ReturnRegion tensionCutoffReturn(
    const MaterialParams& m, const double sigma_tr[3], const double eps_p_bar_n,
    double sigma[3], double& eps_p_bar )
{
    namespace KE = Kokkos::Experimental;
    constexpr int num_sets = 6;
    const ReturnRegion regions[num_sets] = {
        ReturnRegion::TensionPlane,       ReturnRegion::TensionEdge,
        ReturnRegion::TensionApex,        ReturnRegion::MainPlaneTension,
        ReturnRegion::RightTensionCorner, ReturnRegion::LeftTensionCorner };
    const int sizes[num_sets] = { 1, 2, 3, 2, 3, 3 };
    const YieldPlane sets[num_sets][3] = {
        { { 0, -1 }, { 0, -1 }, { 0, -1 } }, // t_1
        { { 0, -1 }, { 1, -1 }, { 0, -1 } }, // t_1, t_2
        { { 0, -1 }, { 1, -1 }, { 2, -1 } }, // t_1, t_2, t_3
        { { 0, 2 }, { 0, -1 }, { 0, -1 } },  // f_13, t_1
        { { 0, 2 }, { 0, 1 }, { 0, -1 } },   // f_13, f_12, t_1
        { { 0, 2 }, { 0, -1 }, { 1, -1 } }   // f_13, t_1, t_2 (+ f_23)
    };
    const double tol =
        1e-12 * ( KE::fabs( sigma_tr[0] ) + KE::fabs( sigma_tr[1] ) +
                  KE::fabs( sigma_tr[2] ) + cohesion( m, eps_p_bar_n ) );

    ReturnRegion best = regions[0];
    double best_v = 0.0;
    for ( int k = 0; k < num_sets; ++k )
    {
        double s_k[3], dgamma[3], eps_k;
        planeReturn( m, sizes[k], sets[k], sigma_tr, eps_p_bar_n, s_k, eps_k,
                     dgamma );
        const double v =
            violation( m, regions[k], sizes[k], s_k, dgamma, eps_k );
        if ( k == 0 || v < best_v )
        {
            best = regions[k];
            best_v = v;
            eps_p_bar = eps_k;
            for ( int i = 0; i < 3; ++i )
                sigma[i] = s_k[i];
        }
        if ( v <= tol )
            break;
    }
    return best;
}

} // namespace Impl
} // namespace physics
} // namespace mpm

#endif // MPM_TENSION_CUTOFF_HPP
