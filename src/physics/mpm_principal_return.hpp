#ifndef MPM_PRINCIPAL_RETURN_HPP
#define MPM_PRINCIPAL_RETURN_HPP

//---------------------------------------------------------------------------//
// Building blocks of the return mappings in principal stresses shared by the
// Mohr-Coulomb surface (mpm_mohr_coulomb.hpp) and its tension cut-off
// (mpm_tension_cutoff.hpp): regions, softened cohesion, principal stresses,
// face gradients and the exact return to Mohr-Coulomb faces.
//---------------------------------------------------------------------------//

#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
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
  With a tension cut-off sigma_1 <= sigma_t (mpm_tension_cutoff.hpp; the
  Rankine planes t_i: sigma_i = sigma_t):
  - TensionPlane: sigma_1 = sigma_t (t_1).
  - TensionEdge: sigma_1 = sigma_2 = sigma_t (t_1, t_2).
  - TensionApex: sigma_1 = sigma_2 = sigma_3 = sigma_t (t_1, t_2, t_3).
  - MainPlaneTension: the line where f_13 = 0 meets sigma_1 = sigma_t.
  - RightTensionCorner: the point where the right edge meets sigma_1 =
    sigma_t (f_13, f_12, t_1; sigma_2 = sigma_3).
  - LeftTensionCorner: the point where the left edge meets the tension edge
    (f_13, f_23, t_1, t_2; sigma_1 = sigma_2 = sigma_t).
*/
enum class ReturnRegion : int
{
    Elastic = 0,
    MainPlane = 1,
    RightEdge = 2,
    LeftEdge = 3,
    Apex = 4,
    TensionPlane = 5,
    TensionEdge = 6,
    TensionApex = 7,
    MainPlaneTension = 8,
    RightTensionCorner = 9,
    LeftTensionCorner = 10
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

//! The in-plane Mohr circle of s = {xx, yy, xy, zz}.
struct MohrCircle
{
    double center;    //!< (s_xx + s_yy) / 2
    double half_diff; //!< (s_xx - s_yy) / 2
    double radius;    //!< sqrt(half_diff^2 + s_xy^2)
};

KOKKOS_INLINE_FUNCTION MohrCircle mohrCircle( const double s[4] )
{
    const double half_diff = 0.5 * ( s[0] - s[1] );
    // sqrt, not hypot: stresses are far from overflow, and hypot is slow.
    return {
        0.5 * ( s[0] + s[1] ), half_diff,
        Kokkos::Experimental::sqrt( half_diff * half_diff + s[2] * s[2] ) };
}

//! In-plane values from the 2x2 problem (Mohr circle), sorted with s_zz.
KOKKOS_INLINE_FUNCTION PrincipalStress principalStress( const double s[4] )
{
    PrincipalStress p;
    const auto [center, half_diff, radius] = mohrCircle( s );
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

//! The major and minor principal stresses of s (s_zz included).
struct PrincipalExtremes
{
    double major; //!< sigma_1
    double minor; //!< sigma_3
};

//! principalStress's sigma[0] and sigma[2] (the same expressions, so the
//! same values, NaN included) without the axes or the sort: all a yield
//! check needs.
KOKKOS_INLINE_FUNCTION PrincipalExtremes principalExtremes( const double s[4] )
{
    const MohrCircle circle = mohrCircle( s );
    const double in_plane_major = circle.center + circle.radius;
    const double in_plane_minor = circle.center - circle.radius;
    return { s[3] > in_plane_major ? s[3] : in_plane_major,
             s[3] > in_plane_minor ? in_plane_minor : s[3] };
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

//! f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi) for s1 >= s3.
KOKKOS_INLINE_FUNCTION double yieldPrincipal( const double s1, const double s3,
                                              const double c,
                                              const double sin_phi,
                                              const double cos_phi )
{
    return ( s1 - s3 ) + ( s1 + s3 ) * sin_phi - 2.0 * c * cos_phi;
}

//! yieldPrincipal of sorted principal stresses sigma[0] >= sigma[2].
KOKKOS_INLINE_FUNCTION double yieldPrincipal( const double sigma[3],
                                              const double c,
                                              const double sin_phi,
                                              const double cos_phi )
{
    return yieldPrincipal( sigma[0], sigma[2], c, sin_phi, cos_phi );
}

//! Gradient of face f_ij (i major, j minor): v_i = 1 + sin, v_j = -(1 - sin).
KOKKOS_INLINE_FUNCTION void faceGradient( const int i, const int j,
                                          const double sin_angle, double v[3] )
{
    v[0] = v[1] = v[2] = 0.0;
    v[i] = 1.0 + sin_angle;
    v[j] = -( 1.0 - sin_angle );
}

//! Increment of the softening measure (MaterialParams::softening_measure)
//! for the deviatoric plastic strain e = e_u - c e_w (principal
//! components): sqrt( 2/3 e : e ), or max_i e_i - min_i e_i = (de_1 - de_3)^p.
KOKKOS_INLINE_FUNCTION double shearIncrement( const MaterialParams& m,
                                              const double e_u[3],
                                              const double e_w[3],
                                              const double c )
{
    namespace KE = Kokkos::Experimental;
    double e[3];
    for ( int i = 0; i < 3; ++i )
        e[i] = e_u[i] - c * e_w[i];
    if ( m.softening_measure == SofteningMeasure::EngineeringShearStrain )
        return KE::fmax( KE::fmax( e[0], e[1] ), e[2] ) -
               KE::fmin( KE::fmin( e[0], e[1] ), e[2] );
    double norm2 = 0.0;
    for ( int i = 0; i < 3; ++i )
        norm2 += e[i] * e[i];
    return KE::sqrt( 2.0 / 3.0 * norm2 );
}

//! d/dc of r(c) = c - c0 - H ( eps_p_bar_n + shearIncrement(c) ), with
//! d_eps = shearIncrement(c): 1 + H sqrt(2/3) (e . e_w) / |e|, or
//! 1 + H ( e_w[i_max] - e_w[i_min] ) for the engineering shear strain.
KOKKOS_INLINE_FUNCTION double softeningResidualSlope( const MaterialParams& m,
                                                      const double e_u[3],
                                                      const double e_w[3],
                                                      const double c,
                                                      const double d_eps )
{
    const double h = m.softening_modulus;
    double e[3];
    for ( int i = 0; i < 3; ++i )
        e[i] = e_u[i] - c * e_w[i];
    if ( m.softening_measure == SofteningMeasure::EngineeringShearStrain )
    {
        int i_max = 0, i_min = 0;
        for ( int i = 1; i < 3; ++i )
        {
            i_max = e[i] > e[i_max] ? i : i_max;
            i_min = e[i] < e[i_min] ? i : i_min;
        }
        return 1.0 + h * ( e_w[i_max] - e_w[i_min] );
    }
    double e_dot_w = 0.0;
    for ( int i = 0; i < 3; ++i )
        e_dot_w += e[i] * e_w[i];
    return d_eps > 0.0 ? 1.0 + h * ( 2.0 / 3.0 ) * e_dot_w / d_eps : 1.0;
}

//! Increment of the softening measure of a return to the apex, where the
//! whole trial deviator is plastic (de_p = dev(sigma_tr) / 2G, principal
//! sigma_tr descending): q_tr / 3G, or (sigma_1 - sigma_3)_tr / 2G.
KOKKOS_INLINE_FUNCTION double apexIncrement( const MaterialParams& m,
                                             const double sigma_tr[3] )
{
    if ( m.softening_measure == SofteningMeasure::EngineeringShearStrain )
        return ( sigma_tr[0] - sigma_tr[2] ) / ( 2.0 * m.shear_modulus );
    const double mean = ( sigma_tr[0] + sigma_tr[1] + sigma_tr[2] ) / 3.0;
    double dev2 = 0.0;
    for ( int i = 0; i < 3; ++i )
        dev2 += ( sigma_tr[i] - mean ) * ( sigma_tr[i] - mean );
    const double q_tr = Kokkos::Experimental::sqrt( 1.5 * dev2 );
    return q_tr / ( 3.0 * m.shear_modulus );
}

//---------------------------------------------------------------------------//
/*!
  \brief Cohesion c (Pa) at the end of a return whose deviatoric plastic
  strain is e(c) = e_u - c e_w: root of r(c) = c - c0 - H ( eps_p_bar_n +
  shearIncrement(c) ) (Eq. 14), or c_r past eps_p_r (Eq. 15).

  r is convex in c (H <= 0); Newton from c_n converges monotonically. A root
  below c_r means the step passes eps_p_r: then c = c_r (H = 0). If dr/dc
  <= 0 (|H| too large against G, snap-back) the iterate is kept.
*/
KOKKOS_INLINE_FUNCTION double softenedCohesion( const MaterialParams& m,
                                                const double e_u[3],
                                                const double e_w[3],
                                                const double eps_p_bar_n )
{
    namespace KE = Kokkos::Experimental;
    const double c0 = m.cohesion_peak;
    const double c_r = m.cohesion_residual;
    const double h = m.softening_modulus;
    double c = cohesion( m, eps_p_bar_n );
    if ( h < 0.0 && c0 + h * eps_p_bar_n > c_r )
    {
        c = c0 + h * eps_p_bar_n;
        for ( int iter = 0; iter < 50; ++iter )
        {
            const double d_eps = shearIncrement( m, e_u, e_w, c );
            const double r = c - c0 - h * ( eps_p_bar_n + d_eps );
            const double dr = softeningResidualSlope( m, e_u, e_w, c, d_eps );
            if ( dr <= 0.0 ) // snap-back: |H| too large for G (ill-posed)
                break;
            const double dc = r / dr;
            c -= dc;
            if ( c <= c_r || KE::fabs( dc ) <= 1e-15 * ( KE::fabs( c ) + c0 ) )
                break;
        }
        c = KE::fmax( c, c_r ); // passed eps_p_r: residual branch, H = 0
    }
    return c;
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
  equation r(c) = c - c0 - H ( eps_p_bar_n + d(eps_p_bar)(c) ) = 0 is solved
  by softenedCohesion (linear, hence one Newton step, for a single face).
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
    double c = softenedCohesion( m, e_u, e_w, eps_p_bar_n );

    // New eps_p_bar; multipliers from c(eps_p_bar) so f = 0 to round-off.
    eps_p_bar = eps_p_bar_n + shearIncrement( m, e_u, e_w, c );
    c = cohesion( m, eps_p_bar );
    for ( int i = 0; i < 3; ++i )
    {
        sigma[i] = sigma_tr[i];
        for ( int k = 0; k < num_faces; ++k )
            sigma[i] -= ( gamma_u[k] - c * gamma_w[k] ) * d_b[k][i];
    }
}

} // namespace Impl

} // namespace physics
} // namespace mpm

#endif // MPM_PRINCIPAL_RETURN_HPP
