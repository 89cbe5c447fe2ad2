#ifndef MPM_MOHR_COULOMB_REFERENCE_HPP
#define MPM_MOHR_COULOMB_REFERENCE_HPP

//---------------------------------------------------------------------------//
// Frozen copy of src/physics/mpm_mohr_coulomb.hpp before the tension cut-off
// (commit b75b148), in namespace mpm::reference_v0 (cohesion() qualified
// against ADL): the tests check that a material without a cut-off returns
// bit-identical results. Do not edit.
//---------------------------------------------------------------------------//

#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace reference_v0
{
using physics::LinearElastic;
using physics::MaterialParams;

//---------------------------------------------------------------------------//
/*!
  \brief Region of the Mohr-Coulomb surface the return mapping ended on.

  Principal stresses are ordered sigma_1 >= sigma_2 >= sigma_3 (tension
  positive). Following de Souza Neto, Peric & Owen (2008, Box 8.5):
  - MainPlane: the face f_13 = 0 (sigma_1, sigma_3), one multiplier.
  - RightEdge: sigma_2 = sigma_3 after return, faces f_13 = f_12 = 0
    (triaxial-extension meridian in soil-mechanics terms).
  - LeftEdge: sigma_1 = sigma_2 after return, faces f_13 = f_23 = 0
    (triaxial-compression meridian).
  - Apex: hydrostatic stress p = c cot(phi).
*/
enum class ReturnRegion : int
{
    Elastic = 0,
    MainPlane = 1,
    RightEdge = 2,
    LeftEdge = 3,
    Apex = 4
};

//---------------------------------------------------------------------------//
/*!
  \brief Cohesion with linear softening, Eqs. 14-15 of Wang, Vardon & Hicks
  (2018): c = max( c0 + H eps_p_bar, c_r ), Pa (H <= 0, eps_p_bar in m/m).
*/
KOKKOS_INLINE_FUNCTION double cohesion( const MaterialParams& m,
                                        const double eps_p_bar )
{
    return Kokkos::Experimental::fmax( m.cohesion_peak +
                                           m.softening_modulus * eps_p_bar,
                                       m.cohesion_residual );
}

namespace Impl
{
//---------------------------------------------------------------------------//
//! Principal stresses of a plane-strain stress s[4] = {xx, yy, xy, zz}.
struct PrincipalStress
{
    double sigma[3];   //!< sorted, sigma[0] >= sigma[1] >= sigma[2], Pa
    int slot[3];       //!< source of sigma[k]: 0 in-plane major, 1 in-plane
                       //!< minor, 2 out-of-plane zz
    double cos_2theta; //!< cos(2 theta), theta = in-plane major direction
    double sin_2theta; //!< sin(2 theta)
};

//! In-plane values from the 2x2 problem (Mohr circle), sorted with s_zz.
KOKKOS_INLINE_FUNCTION PrincipalStress principalStress( const double s[4] )
{
    PrincipalStress p;
    const double center = 0.5 * ( s[0] + s[1] );
    const double half_diff = 0.5 * ( s[0] - s[1] );
    // sqrt, not hypot: stresses are far from overflow, and hypot is slow.
    const double radius =
        Kokkos::Experimental::sqrt( half_diff * half_diff + s[2] * s[2] );
    p.cos_2theta = radius > 0.0 ? half_diff / radius : 1.0;
    p.sin_2theta = radius > 0.0 ? s[2] / radius : 0.0;
    const double in_plane[3] = { center + radius, center - radius, s[3] };
    // Insert sigma_zz into the ordered pair (major, minor).
    int order[3] = { 0, 1, 2 };
    if ( s[3] > in_plane[0] )
    {
        order[0] = 2;
        order[1] = 0;
        order[2] = 1;
    }
    else if ( s[3] > in_plane[1] )
    {
        order[1] = 2;
        order[2] = 1;
    }
    for ( int k = 0; k < 3; ++k )
    {
        p.slot[k] = order[k];
        p.sigma[k] = in_plane[order[k]];
    }
    return p;
}

//! Rotate new principal values back to {xx, yy, xy, zz} with the trial axes.
KOKKOS_INLINE_FUNCTION void fromPrincipal( const PrincipalStress& p,
                                           const double sigma[3], double s[4] )
{
    double by_slot[3];
    for ( int k = 0; k < 3; ++k )
        by_slot[p.slot[k]] = sigma[k];
    const double center = 0.5 * ( by_slot[0] + by_slot[1] );
    const double radius = 0.5 * ( by_slot[0] - by_slot[1] );
    s[0] = center + radius * p.cos_2theta;
    s[1] = center - radius * p.cos_2theta;
    s[2] = radius * p.sin_2theta;
    s[3] = by_slot[2];
}

//! f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi) for sorted s1 >= s3.
KOKKOS_INLINE_FUNCTION double yieldPrincipal( const double sigma[3],
                                              const double c,
                                              const double sin_phi,
                                              const double cos_phi )
{
    return ( sigma[0] - sigma[2] ) + ( sigma[0] + sigma[2] ) * sin_phi -
           2.0 * c * cos_phi;
}

//! Gradient of face f_ij (i major, j minor): v_i = 1 + sin, v_j = -(1 - sin).
KOKKOS_INLINE_FUNCTION void faceGradient( const int i, const int j,
                                          const double sin_angle, double v[3] )
{
    v[0] = v[1] = v[2] = 0.0;
    v[i] = 1.0 + sin_angle;
    v[j] = -( 1.0 - sin_angle );
}

//! d(eps_p_bar) = sqrt( 2/3 e : e ) of the deviatoric plastic strain
//! e = e_u - c e_w (principal components).
KOKKOS_INLINE_FUNCTION double
shearIncrement( const double e_u[3], const double e_w[3], const double c )
{
    double norm2 = 0.0;
    for ( int i = 0; i < 3; ++i )
        norm2 += ( e_u[i] - c * e_w[i] ) * ( e_u[i] - c * e_w[i] );
    return Kokkos::Experimental::sqrt( 2.0 / 3.0 * norm2 );
}

//---------------------------------------------------------------------------//
/*!
  \brief Exact return to one face (num_faces = 1) or one edge (two faces) in
  principal space; returns sigma (Pa) and the new eps_p_bar.

  sigma = sigma_tr - sum_k dgamma_k D b_k, with a_k, b_k the gradients of f and
  g (phi -> psi) of face k and D_ij = lambda + 2 G delta_ij. For a fixed
  cohesion c the consistency conditions a_k . sigma = 2 c cos(phi) are linear:
  dgamma(c) = A^-1 ( a . sigma_tr - 2 c cos(phi) ), A_kl = a_k . D b_l.
  The deviatoric plastic strain is e(c) = dev( sum_k dgamma_k(c) b_k ) and
  d(eps_p_bar) = sqrt( 2/3 e : e ). On the softening branch the scalar
  equation r(c) = c - c0 - H ( eps_p_bar_n + d(eps_p_bar)(c) ) = 0 is convex
  in c (H <= 0); Newton from c_n converges monotonically (linear, hence one
  step, for a single face). A root below c_r means the step passes
  eps_p_r = (c_r - c0) / H: then c = c_r (H = 0) is solved exactly.
  Uniqueness needs dr/dc > 0, i.e. |H| small against G (for the main plane
  A + 2 cos(phi) H 2/3 sqrt(3 + sin^2 psi) > 0); otherwise c_n is kept.
*/
KOKKOS_INLINE_FUNCTION void
faceReturn( const MaterialParams& m, const int num_faces, const int faces[2][2],
            const double sigma_tr[3], const double eps_p_bar_n, double sigma[3],
            double& eps_p_bar )
{
    namespace KE = Kokkos::Experimental;
    const double sin_phi = m.sin_phi;
    const double cos_phi = m.cos_phi;
    const double sin_psi = m.sin_psi;
    const double two_g = 2.0 * m.shear_modulus;
    const double lambda = m.bulk_modulus - two_g / 3.0;

    // Face gradients a_k, flow directions b_k and D b_k.
    double a[2][3] = {}, b[2][3] = {}, d_b[2][3] = {};
    for ( int k = 0; k < num_faces; ++k )
    {
        faceGradient( faces[k][0], faces[k][1], sin_phi, a[k] );
        faceGradient( faces[k][0], faces[k][1], sin_psi, b[k] );
        const double lambda_tr = lambda * ( b[k][0] + b[k][1] + b[k][2] );
        for ( int i = 0; i < 3; ++i )
            d_b[k][i] = lambda_tr + two_g * b[k][i];
    }

    // Consistency matrix A_kl = a_k . D b_l and its inverse (1x1 or 2x2).
    double mat[2][2] = { { 1.0, 0.0 }, { 0.0, 1.0 } };
    for ( int k = 0; k < num_faces; ++k )
        for ( int l = 0; l < num_faces; ++l )
            mat[k][l] =
                a[k][0] * d_b[l][0] + a[k][1] * d_b[l][1] + a[k][2] * d_b[l][2];
    const double det = mat[0][0] * mat[1][1] - mat[0][1] * mat[1][0];
    const double inv[2][2] = { { mat[1][1] / det, -mat[0][1] / det },
                               { -mat[1][0] / det, mat[0][0] / det } };

    // Affine multipliers dgamma(c) = gamma_u - c gamma_w.
    double a_sigma[2] = { 0.0, 0.0 };
    for ( int k = 0; k < num_faces; ++k )
        a_sigma[k] = a[k][0] * sigma_tr[0] + a[k][1] * sigma_tr[1] +
                     a[k][2] * sigma_tr[2];
    double gamma_u[2], gamma_w[2];
    for ( int k = 0; k < 2; ++k )
    {
        gamma_u[k] = inv[k][0] * a_sigma[0] + inv[k][1] * a_sigma[1];
        gamma_w[k] = 2.0 * cos_phi * ( inv[k][0] + inv[k][1] );
    }
    if ( num_faces == 1 )
    {
        gamma_u[1] = gamma_w[1] = 0.0;
    }

    // Deviatoric plastic strain e(c) = e_u - c e_w.
    // Every face has tr(b_k) = 2 sin(psi).
    double e_u[3], e_w[3];
    for ( int i = 0; i < 3; ++i )
    {
        e_u[i] = 0.0;
        e_w[i] = 0.0;
        for ( int k = 0; k < num_faces; ++k )
        {
            e_u[i] += gamma_u[k] * ( b[k][i] - 2.0 * sin_psi / 3.0 );
            e_w[i] += gamma_w[k] * ( b[k][i] - 2.0 * sin_psi / 3.0 );
        }
    }

    // Solve the consistency condition for the new cohesion.
    const double c0 = m.cohesion_peak;
    const double c_r = m.cohesion_residual;
    const double h = m.softening_modulus;
    double c = reference_v0::cohesion( m, eps_p_bar_n );
    if ( h < 0.0 && c0 + h * eps_p_bar_n > c_r )
    {
        c = c0 + h * eps_p_bar_n;
        for ( int iter = 0; iter < 50; ++iter )
        {
            const double d_eps = shearIncrement( e_u, e_w, c );
            const double r = c - c0 - h * ( eps_p_bar_n + d_eps );
            // dr/dc = 1 + H sqrt(2/3) (e . e_w) / |e|.
            double e_dot_w = 0.0;
            for ( int i = 0; i < 3; ++i )
                e_dot_w += ( e_u[i] - c * e_w[i] ) * e_w[i];
            const double dr =
                d_eps > 0.0 ? 1.0 + h * ( 2.0 / 3.0 ) * e_dot_w / d_eps : 1.0;
            if ( dr <= 0.0 ) // snap-back: |H| too large for G (ill-posed)
                break;
            const double dc = r / dr;
            c -= dc;
            if ( c <= c_r || KE::fabs( dc ) <= 1e-15 * ( KE::fabs( c ) + c0 ) )
                break;
        }
        c = KE::fmax( c, c_r ); // passed eps_p_r: residual branch, H = 0
    }

    // New eps_p_bar; multipliers from c(eps_p_bar) so f = 0 to round-off.
    eps_p_bar = eps_p_bar_n + shearIncrement( e_u, e_w, c );
    c = reference_v0::cohesion( m, eps_p_bar );
    for ( int i = 0; i < 3; ++i )
    {
        sigma[i] = sigma_tr[i];
        for ( int k = 0; k < num_faces; ++k )
            sigma[i] -= ( gamma_u[k] - c * gamma_w[k] ) * d_b[k][i];
    }
}

} // namespace Impl

//---------------------------------------------------------------------------//
/*!
  \brief Mohr-Coulomb yield function with the cohesion of Eqs. 14-15 of Wang,
  Vardon & Hicks (2018), Pa: f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi),
  principal stresses s1 >= s2 >= s3 (tension positive, s_zz included).
*/
KOKKOS_INLINE_FUNCTION double yieldFunction( const MaterialParams& m,
                                             const double s[4],
                                             const double eps_p_bar )
{
    const Impl::PrincipalStress p = Impl::principalStress( s );
    return Impl::yieldPrincipal(
        p.sigma, reference_v0::cohesion( m, eps_p_bar ), m.sin_phi, m.cos_phi );
}

//---------------------------------------------------------------------------//
/*!
  \brief Non-associated Mohr-Coulomb with linear cohesion softening (Eqs.
  14-15 of Wang, Vardon & Hicks 2018); stress in Pa, strain in m/m.

  Elastic predictor (LinearElastic) and exact return mapping in principal
  stresses (de Souza Neto, Peric & Owen 2008, Sec. 8.2; Clausen, Damkilde &
  Andersen 2006): main plane, then the right or left edge, then the apex.
  Plastic potential g: f with phi replaced by the dilation angle psi.

  eps_p_bar is the accumulated plastic shear strain invariant,
    eps_p_bar = sum over steps of sqrt( 2/3 de_p : de_p ),
  de_p the deviatoric part of the plastic strain increment of the step.
  - Main plane: d(eps_p_bar) = 2/3 sqrt( 3 + sin^2 psi ) dgamma.
  - Edges: sqrt(2/3) |dev( dgamma_a b_a + dgamma_b b_b )|, solved with
    the cohesion by a scalar Newton iteration (Impl::faceReturn).
  - Apex: de_p = dev(sigma_tr) / 2G, so d(eps_p_bar) = q_tr / 3G (q_tr the
    von Mises stress of the trial), independent of c; then
    p = c(eps_p_bar_new) cot(phi).
*/
struct MohrCoulomb
{
    //! Elastic predictor with de, then return mapping (updates s, eps_p_bar).
    KOKKOS_INLINE_FUNCTION ReturnRegion operator()( const MaterialParams& m,
                                                    const double de[4],
                                                    double s[4],
                                                    double& eps_p_bar ) const
    {
        LinearElastic{}( m, de, s );
        return returnMap( m, s, eps_p_bar );
    }

    //! Return mapping from the trial stress s (updated in place).
    KOKKOS_INLINE_FUNCTION ReturnRegion returnMap( const MaterialParams& m,
                                                   double s[4],
                                                   double& eps_p_bar ) const
    {
        namespace KE = Kokkos::Experimental;
        const double sin_phi = m.sin_phi;
        const double cos_phi = m.cos_phi;
        const double sin_psi = m.sin_psi;

        // Trial principal stresses and yield check.
        const Impl::PrincipalStress p = Impl::principalStress( s );
        const double* sigma_tr = p.sigma;
        const double c_n = reference_v0::cohesion( m, eps_p_bar );
        if ( Impl::yieldPrincipal( sigma_tr, c_n, sin_phi, cos_phi ) <= 0.0 )
            return ReturnRegion::Elastic;
        const double tol =
            1e-12 * ( KE::fabs( sigma_tr[0] ) + KE::fabs( sigma_tr[2] ) + c_n );

        // Main plane f_13.
        double sigma[3];
        double eps_p_bar_new = eps_p_bar;
        ReturnRegion region = ReturnRegion::MainPlane;
        const int main_face[2][2] = { { 0, 2 }, { 0, 2 } };
        Impl::faceReturn( m, 1, main_face, sigma_tr, eps_p_bar, sigma,
                          eps_p_bar_new );
        if ( sigma[0] < sigma[1] - tol || sigma[1] < sigma[2] - tol )
        {
            // Edge: right if sigma_2 = sigma_3 is reached first along D b.
            const bool right =
                ( 1.0 - sin_psi ) * ( sigma_tr[0] - sigma_tr[1] ) -
                    ( 1.0 + sin_psi ) * ( sigma_tr[1] - sigma_tr[2] ) >
                0.0;
            const int right_faces[2][2] = { { 0, 2 }, { 0, 1 } };
            const int left_faces[2][2] = { { 0, 2 }, { 1, 2 } };
            Impl::faceReturn( m, 2, right ? right_faces : left_faces, sigma_tr,
                              eps_p_bar, sigma, eps_p_bar_new );
            region = right ? ReturnRegion::RightEdge : ReturnRegion::LeftEdge;
            // Past the apex (p > c cot(phi)) the edge ordering is inverted.
            const bool past_apex =
                right ? sigma[0] < sigma[1] - tol : sigma[1] < sigma[2] - tol;
            if ( past_apex && sin_phi > 1e-12 )
            {
                // Apex: d(eps_p_bar) = q_tr / 3G, p = c(eps_p_bar) cot(phi).
                const double mean =
                    ( sigma_tr[0] + sigma_tr[1] + sigma_tr[2] ) / 3.0;
                double dev2 = 0.0;
                for ( int i = 0; i < 3; ++i )
                    dev2 += ( sigma_tr[i] - mean ) * ( sigma_tr[i] - mean );
                const double q_tr = KE::sqrt( 1.5 * dev2 );
                eps_p_bar_new = eps_p_bar + q_tr / ( 3.0 * m.shear_modulus );
                const double p_apex =
                    reference_v0::cohesion( m, eps_p_bar_new ) * cos_phi /
                    sin_phi;
                sigma[0] = sigma[1] = sigma[2] = p_apex;
                region = ReturnRegion::Apex;
            }
        }

        // Rotate back with the trial in-plane principal directions.
        Impl::fromPrincipal( p, sigma, s );
        eps_p_bar = eps_p_bar_new;
        return region;
    }
};

} // namespace reference_v0
} // namespace mpm

#endif // MPM_MOHR_COULOMB_REFERENCE_HPP
