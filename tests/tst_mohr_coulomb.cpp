#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>

#include <mpm_test_principal.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace
{
using namespace mpm_test::return_mapping;
using mpm::physics::yieldFunction;

const double pi = std::acos( -1.0 );

// E = 10 MPa, nu = 0.3, c0 = 10 kPa, c_r = 2 kPa, H = -250 kPa,
// phi = 30 deg, psi = 10 deg (psi != phi so that swapping them fails).
MaterialParams testParams( const double psi_deg = 10.0 )
{
    MaterialParams m = mpm::physics::elasticParams( 1.0e7, 0.3, 2000.0 );
    m.model = mpm::physics::Model::MohrCoulomb;
    m.cohesion_peak = 10.0e3;
    m.cohesion_residual = 2.0e3;
    m.softening_modulus = -250.0e3;
    m.setAngles( 30.0 * pi / 180.0, psi_deg * pi / 180.0 );
    return m;
}

// Residual plastic shear strain eps_p_r = (c_r - c0) / H (Eq. 15).
double epsResidual( const MaterialParams& m )
{
    return ( m.cohesion_residual - m.cohesion_peak ) / m.softening_modulus;
}

// The MC yield function written out here: f and its scale
// 2c cos(phi) + |s1 + s3| sin(phi) + |s1 - s3|.
double yieldRef( const MaterialParams& m, const double s[4], const double eps,
                 double* scale = nullptr )
{
    const auto p = principal( s );
    const double sin_phi = std::sin( m.friction_angle );
    const double two_c_cos =
        2.0 * cohesionRef( m, eps ) * std::cos( m.friction_angle );
    if ( scale )
        *scale = two_c_cos + std::fabs( p[0] + p[2] ) * sin_phi +
                 std::fabs( p[0] - p[2] );
    return ( p[0] - p[2] ) + ( p[0] + p[2] ) * sin_phi - two_c_cos;
}

// Trial stresses {xx, yy, xy, zz} (Pa), all with sigma_1 = xx, sigma_2 = zz,
// sigma_3 = yy: well inside the main plane region, sigma_2 close to sigma_3
// (right edge), sigma_1 close to sigma_2 (left edge); tension past the apex.
const double main_tr[4] = { -30.0e3, -160.0e3, 0.0, -80.0e3 };
const double right_tr[4] = { -20.0e3, -155.0e3, 0.0, -150.0e3 };
const double left_tr[4] = { -20.0e3, -160.0e3, 0.0, -25.0e3 };
const double apex_tr[4] = { 30.0e3, 20.0e3, 4.0e3, 25.0e3 };
const ReturnRegion expected[3] = {
    ReturnRegion::MainPlane, ReturnRegion::RightEdge, ReturnRegion::LeftEdge };

// Return from s_tr; checks shared by all plastic returns: f = 0, the eps_p_bar
// increment equals sqrt(2/3 de_p : de_p) (or (de_1 - de_3), with the
// engineering measure) of de_p = C : (s_tr - s).
ReturnRegion checkedReturn( const MaterialParams& m, const double s_tr[4],
                            const double eps_n, double s[4], double& eps )
{
    std::copy( s_tr, s_tr + 4, s );
    eps = eps_n;
    const ReturnRegion region = MohrCoulomb{}.returnMap( m, s, eps );
    if ( region == ReturnRegion::Elastic )
        return region;
    double scale;
    const double f = yieldRef( m, s, eps, &scale );
    EXPECT_NEAR( f, 0.0, 1e-10 * scale );
    EXPECT_NEAR( yieldFunction( m, s, eps ), 0.0, 1e-10 * scale );
    EXPECT_NEAR( cohesion( m, eps ), cohesionRef( m, eps ), 1e-12 * 1e4 );
    const double d_eps =
        softeningIncrementRef( m, plasticStrain( m, s_tr, s ) );
    EXPECT_GT( eps - eps_n, 0.0 );
    EXPECT_NEAR( eps - eps_n, d_eps, 1e-9 * d_eps + 1e-16 );
    return region;
}

TEST( MohrCoulomb, cohesion_softens_linearly_then_stays_residual )
{
    const auto m = testParams();
    const double eps_r = epsResidual( m ); // 0.032
    EXPECT_DOUBLE_EQ( cohesion( m, 0.0 ), 10.0e3 );
    EXPECT_NEAR( cohesion( m, 0.01 ), 10.0e3 - 2.5e3, 1e-9 );
    EXPECT_NEAR( cohesion( m, eps_r ), 2.0e3, 1e-9 );
    EXPECT_DOUBLE_EQ( cohesion( m, 0.1 ), 2.0e3 );
}

TEST( MohrCoulomb, elastic_trial_is_unchanged )
{
    const auto m = testParams();
    const double s_tr[4] = { -50.0e3, -60.0e3, 3.0e3, -55.0e3 };
    ASSERT_LT( yieldRef( m, s_tr, 0.0 ), 0.0 );
    double s[4] = { s_tr[0], s_tr[1], s_tr[2], s_tr[3] }, eps = 0.005;
    EXPECT_EQ( MohrCoulomb{}.returnMap( m, s, eps ), ReturnRegion::Elastic );
    for ( int i = 0; i < 4; ++i )
        EXPECT_EQ( s[i], s_tr[i] );
    EXPECT_EQ( eps, 0.005 );
}

// The elastic check's major and minor principal stresses are the sorted
// principal values' first and last, bit for bit, whichever place s_zz takes
// (above, between and below the in-plane pair, and tied with one), and a
// NaN trial is not elastic.
TEST( MohrCoulomb, principal_extremes_are_the_sorted_values_ends )
{
    namespace Impl = mpm::physics::Impl;
    const double in_plane[3] = { -50.0e3, -60.0e3, 3.0e3 };
    const double center = 0.5 * ( in_plane[0] + in_plane[1] );
    const double radius =
        std::sqrt( 25.0e6 + in_plane[2] * in_plane[2] ); // (5 kPa, 3 kPa)
    for ( const double s_zz :
          { -40.0e3, -55.0e3, -70.0e3, center + radius, center - radius } )
    {
        const double s[4] = { in_plane[0], in_plane[1], in_plane[2], s_zz };
        const Impl::PrincipalExtremes extremes = Impl::principalExtremes( s );
        const Impl::PrincipalStress sorted = Impl::principalStress( s );
        const auto reference = mpm_test::principal( s );
        EXPECT_EQ( extremes.major, sorted.sigma[0] ) << "s_zz " << s_zz;
        EXPECT_EQ( extremes.minor, sorted.sigma[2] ) << "s_zz " << s_zz;
        EXPECT_NEAR( extremes.major, reference[0], 1e-9 ) << "s_zz " << s_zz;
        EXPECT_NEAR( extremes.minor, reference[2], 1e-9 ) << "s_zz " << s_zz;
    }
    const auto m = testParams();
    double s[4] = { std::nan( "" ), -60.0e3, 3.0e3, -55.0e3 }, eps = 0.0;
    EXPECT_NE( MohrCoulomb{}.returnMap( m, s, eps ), ReturnRegion::Elastic );
}

// Flow de_p = dgamma (1 + sin psi, 0, -(1 - sin psi)) in (1, 2, 3): the
// closest point in the energy norm.
TEST( MohrCoulomb, main_plane_return_lies_on_surface )
{
    const auto m = testParams();
    const double sin_psi = std::sin( m.dilation_angle );
    const double* s_tr = main_tr;
    double s[4], eps;
    ASSERT_EQ( checkedReturn( m, s_tr, 0.004, s, eps ),
               ReturnRegion::MainPlane );
    EXPECT_GT( s[0], s[3] );
    EXPECT_GT( s[3], s[1] );
    EXPECT_EQ( s[2], 0.0 );
    const auto de_p = plasticStrain( m, s_tr, s );
    const double dgamma = de_p[0] / ( 1.0 + sin_psi );
    EXPECT_GT( dgamma, 0.0 );
    EXPECT_NEAR( de_p[3], 0.0, 1e-10 * de_p[0] );
    EXPECT_NEAR( de_p[1], -( 1.0 - sin_psi ) * dgamma, 1e-10 * de_p[0] );
    // d(eps_p_bar) = 2/3 sqrt(3 + sin^2 psi) dgamma on the main plane.
    const double d_eps =
        2.0 / 3.0 * std::sqrt( 3.0 + sin_psi * sin_psi ) * dgamma;
    EXPECT_NEAR( eps - 0.004, d_eps, 1e-10 * d_eps );
    // Softening branch: c = c0 + H eps_p_bar (Eq. 14).
    EXPECT_NEAR( cohesion( m, eps ), 10.0e3 - 250.0e3 * eps, 1e-8 );
}

// Softening on the engineering plastic shear strain: on the main plane
// d(eps_1 - eps_3)^p = 2 dgamma, so the return equals the paper's measure's
// with H scaled by 3 / sqrt(3 + sin^2 psi) (its stress and cohesion), and
// eps_p_bar grows by that factor more; at the apex by (s_1 - s_3)_tr / 2G.
TEST( MohrCoulomb, engineering_shear_strain_measure_on_main_plane_and_apex )
{
    auto m = testParams();
    m.softening_measure = SofteningMeasure::EngineeringShearStrain;
    const double sin_psi = std::sin( m.dilation_angle );
    const double ratio = 3.0 / std::sqrt( 3.0 + sin_psi * sin_psi );
    double s[4], eps;
    ASSERT_EQ( checkedReturn( m, main_tr, 0.004, s, eps ),
               ReturnRegion::MainPlane );
    const auto de_p = plasticStrain( m, main_tr, s );
    const double dgamma = de_p[0] / ( 1.0 + sin_psi );
    EXPECT_NEAR( eps - 0.004, 2.0 * dgamma, 1e-10 * dgamma );

    auto m_eq = testParams();
    m_eq.softening_modulus = m.softening_modulus * ratio;
    double s_eq[4], eps_eq;
    ASSERT_EQ( checkedReturn( m_eq, main_tr, 0.004 / ratio, s_eq, eps_eq ),
               ReturnRegion::MainPlane );
    for ( int i = 0; i < 4; ++i )
        EXPECT_NEAR( s[i], s_eq[i], 1e-9 * 160.0e3 ) << i;
    EXPECT_NEAR( eps, eps_eq * ratio, 1e-10 * eps );

    ASSERT_EQ( checkedReturn( m, apex_tr, 0.001, s, eps ), ReturnRegion::Apex );
    const auto p_tr = principal( apex_tr );
    EXPECT_NEAR( eps - 0.001, ( p_tr[0] - p_tr[2] ) / ( 2.0 * m.shear_modulus ),
                 1e-12 );
}

/*!
  \brief The return of `s_tr` onto an edge: the right edge (sigma_2 =
  sigma_3, de_p = ga (1+sp, 0, -(1-sp)) + gb (1+sp, -(1-sp), 0)) or the left
  edge (sigma_1 = sigma_2, de_p = ga (1+sp, 0, -(1-sp)) + gb (0, 1+sp,
  -(1-sp))), with ga, gb >= 0 (sigma_1 = xx, sigma_2 = zz, sigma_3 = yy).
*/
void expectEdgeReturn( const double* s_tr, const ReturnRegion region )
{
    const auto m = testParams();
    const double sin_psi = std::sin( m.dilation_angle );
    double s[4], eps;
    ASSERT_EQ( checkedReturn( m, s_tr, 0.002, s, eps ), region );
    const bool right = region == ReturnRegion::RightEdge;
    if ( right )
    {
        EXPECT_NEAR( s[3], s[1], 1e-10 * std::fabs( s[1] ) );
        EXPECT_GT( s[0], s[3] );
    }
    else
    {
        EXPECT_NEAR( s[0], s[3], 1e-10 * std::fabs( s[0] ) );
        EXPECT_GT( s[3], s[1] );
    }
    const auto de_p = plasticStrain( m, s_tr, s );
    // ga and gb from the components of one plane's flow each (yy or xx, and
    // zz), then the component both flows share (xx or yy).
    const double own = right ? -( 1.0 - sin_psi ) : 1.0 + sin_psi;
    const double gamma_a = de_p[right ? 1 : 0] / own;
    const double gamma_b = de_p[3] / own;
    EXPECT_GT( gamma_a, 0.0 );
    EXPECT_GT( gamma_b, 0.0 );
    const int shared = right ? 0 : 1;
    EXPECT_NEAR( de_p[shared],
                 ( gamma_a + gamma_b ) *
                     ( right ? 1.0 + sin_psi : -( 1.0 - sin_psi ) ),
                 1e-10 * std::fabs( de_p[shared] ) );
}

TEST( MohrCoulomb, right_edge_return_has_equal_minor_stresses )
{
    expectEdgeReturn( right_tr, ReturnRegion::RightEdge );
}

TEST( MohrCoulomb, left_edge_return_has_equal_major_stresses )
{
    expectEdgeReturn( left_tr, ReturnRegion::LeftEdge );
}

// Tensile trial beyond the apex: hydrostatic p = c(eps_p_bar) cot(phi) with
// d(eps_p_bar) = q_tr / 3G (the trial deviator is all plastic).
TEST( MohrCoulomb, apex_return_is_hydrostatic_at_c_cot_phi )
{
    const auto m = testParams();
    const double* s_tr = apex_tr;
    double s[4], eps;
    ASSERT_EQ( checkedReturn( m, s_tr, 0.002, s, eps ), ReturnRegion::Apex );
    const double p = s[0];
    EXPECT_EQ( s[1], p );
    EXPECT_EQ( s[3], p );
    EXPECT_NEAR( s[2], 0.0, 1e-12 * p );
    EXPECT_NEAR( p, cohesionRef( m, eps ) / std::tan( m.friction_angle ),
                 1e-12 * p );
    const double mean = ( s_tr[0] + s_tr[1] + s_tr[3] ) / 3.0;
    double dev2 = 2.0 * s_tr[2] * s_tr[2]; // q_tr = sqrt(3/2 dev : dev)
    for ( int i : { 0, 1, 3 } )
        dev2 += ( s_tr[i] - mean ) * ( s_tr[i] - mean );
    const double q_tr = std::sqrt( 1.5 * dev2 );
    EXPECT_NEAR( eps - 0.002, q_tr / ( 3.0 * m.shear_modulus ), 1e-12 * eps );
    EXPECT_LT( p, mean ); // plastic dilation
}

// A step that starts just before eps_p_r ends on the residual branch.
TEST( MohrCoulomb, return_past_residual_strain_uses_residual_cohesion )
{
    const auto m = testParams();
    const double eps_n = epsResidual( m ) - 1.0e-4;
    int k = 0;
    for ( const double* s_tr : { main_tr, right_tr, left_tr } )
    {
        double s[4], eps;
        ASSERT_EQ( checkedReturn( m, s_tr, eps_n, s, eps ), expected[k++] );
        EXPECT_GT( eps, epsResidual( m ) );
        EXPECT_DOUBLE_EQ( cohesion( m, eps ), m.cohesion_residual );
    }
}

TEST( MohrCoulomb, perfect_plasticity_and_tresca_limit_return_to_surface )
{
    auto perfect = testParams();
    perfect.softening_modulus = 0.0; // H = 0
    auto flat = testParams();
    flat.cohesion_residual = flat.cohesion_peak; // c0 == c_r
    auto tresca = testParams( 0.0 );
    tresca.setAngles( 0.0, 0.0 ); // phi = psi = 0
    tresca.cohesion_peak = 40.0e3;
    tresca.softening_modulus = 0.0;
    for ( const auto& m : { perfect, flat, tresca } )
    {
        int k = 0;
        for ( const double* s_tr : { main_tr, right_tr, left_tr } )
        {
            double s[4], eps;
            EXPECT_EQ( checkedReturn( m, s_tr, 0.001, s, eps ), expected[k++] );
            EXPECT_DOUBLE_EQ( cohesion( m, eps ), m.cohesion_peak );
            for ( int i = 0; i < 4; ++i )
                EXPECT_TRUE( std::isfinite( s[i] ) );
        }
    }
    // Tresca has no apex: a tensile hydrostatic trial is elastic.
    double s[4] = { 1.0e6, 1.0e6, 0.0, 1.0e6 }, eps = 0.0;
    EXPECT_EQ( MohrCoulomb{}.returnMap( tresca, s, eps ),
               ReturnRegion::Elastic );
}

// Random trials (rotated, xy != 0): every plastic return is on the surface,
// coaxial with the trial (same in-plane principal axes), and its plastic strain
// is a non-negative combination of the flow directions of its region; each
// region is visited.
TEST( MohrCoulomb, random_trials_satisfy_consistency_in_every_region )
{
    std::mt19937 gen( 20180801 );
    std::uniform_real_distribution<double> normal( -300.0e3, 60.0e3 );
    std::uniform_real_distribution<double> shear( -80.0e3, 80.0e3 );
    std::uniform_real_distribution<double> strain( 0.0, 0.045 );
    int visits[5] = { 0, 0, 0, 0, 0 };
    for ( const auto measure : { SofteningMeasure::EquivalentPlasticStrain,
                                 SofteningMeasure::EngineeringShearStrain } )
        for ( const double psi_deg : { 0.0, 10.0, 30.0 } )
        {
            auto m = testParams( psi_deg );
            m.softening_measure = measure;
            const double sp = std::sin( m.dilation_angle );
            for ( int n = 0; n < 20000; ++n )
            {
                const double s_tr[4] = { normal( gen ), normal( gen ),
                                         shear( gen ), normal( gen ) };
                const double eps_n = strain( gen );
                double s[4], eps;
                const ReturnRegion region =
                    checkedReturn( m, s_tr, eps_n, s, eps );
                ++visits[static_cast<int>( region )];
                double scale;
                const double f_tr = yieldRef( m, s_tr, eps_n, &scale );
                EXPECT_EQ( region == ReturnRegion::Elastic, f_tr <= 0.0 );
                if ( region == ReturnRegion::Elastic )
                    continue;
                // Coaxial: the 2x2 commutator of s and s_tr vanishes.
                EXPECT_NEAR( ( s[0] - s[1] ) * s_tr[2] -
                                 ( s_tr[0] - s_tr[1] ) * s[2],
                             0.0, 1e-10 * scale * scale );
                const auto sig = principal( s );
                const auto d = principal( plasticStrain( m, s_tr, s ).data() );
                const double tol =
                    1e-9 * ( std::fabs( d[0] ) + std::fabs( d[2] ) );
                const bool right = region == ReturnRegion::RightEdge;
                const bool left = region == ReturnRegion::LeftEdge;
                if ( region == ReturnRegion::Apex )
                {
                    EXPECT_NEAR( sig[0], sig[2], 1e-12 * scale );
                    EXPECT_NEAR( sig[0],
                                 cohesionRef( m, eps ) /
                                     std::tan( m.friction_angle ),
                                 1e-12 * scale );
                    continue;
                }
                // de_p = sum_k dgamma_k b_k, dgamma_k >= 0: main d2 = 0; right
                // (s2 = s3) d2 <= 0; left (s1 = s2) d2 >= 0; and
                // (1 - sin psi) (positive part) = -(1 + sin psi) (negative
                // part).
                EXPECT_LE( right  ? d[1]
                           : left ? -d[1]
                                  : std::fabs( d[1] ),
                           tol );
                EXPECT_NEAR( ( d[0] + ( left ? d[1] : 0.0 ) ) * ( 1.0 - sp ),
                             -( d[2] + ( right ? d[1] : 0.0 ) ) * ( 1.0 + sp ),
                             tol );
                // Edges: the two principal stresses of the edge are equal.
                const double gap = right  ? sig[1] - sig[2]
                                   : left ? sig[0] - sig[1]
                                          : 0.0;
                EXPECT_NEAR( gap, 0.0, 1e-10 * scale );
            }
        }
    for ( int r = 0; r < 5; ++r )
        EXPECT_GT( visits[r], 100 ) << "region " << r;
}

// Simple shear (de_xy only) from isotropic compression p0, psi = 0 so the
// normal stresses stay at -p0 and tau = s_xy: sigma_1,3 = -p0 -+ tau
// (in-plane), sigma_2 = s_zz. On yield tau = c(eps_p_bar) cos(phi) +
// p0 sin(phi) and eps_p_bar = 2/sqrt(3) (eps_xy - tau / 2G); hence
//   tau (1 + 2/sqrt(3) H cos(phi) / 2G) = (c0 + 2/sqrt(3) H eps_xy) cos(phi)
//                                         + p0 sin(phi)   (Eq. 14)
// until tau_r = c_r cos(phi) + p0 sin(phi) (Eq. 15).
TEST( MohrCoulomb, simple_shear_softens_from_peak_to_residual )
{
    const auto m = testParams( 0.0 );
    const double p0 = 100.0e3, two_g = 2.0 * m.shear_modulus;
    const double sin_phi = std::sin( m.friction_angle ),
                 cos_phi = std::cos( m.friction_angle );
    const double k = 2.0 / std::sqrt( 3.0 ) * m.softening_modulus;
    const double tau_peak = m.cohesion_peak * cos_phi + p0 * sin_phi;
    const double tau_res = m.cohesion_residual * cos_phi + p0 * sin_phi;
    double s[4] = { -p0, -p0, 0.0, -p0 }, eps = 0.0, eps_xy = 0.0;
    const double de[4] = { 0.0, 0.0, 1.0e-5, 0.0 };
    int softening_steps = 0, residual_steps = 0;
    for ( int step = 0; step < 6000; ++step )
    {
        const ReturnRegion region = MohrCoulomb{}( m, de, s, eps );
        eps_xy += de[2];
        const double tau = s[2];
        const double tau_soft =
            ( ( m.cohesion_peak + k * eps_xy ) * cos_phi + p0 * sin_phi ) /
            ( 1.0 + k * cos_phi / two_g );
        const double tau_exact = eps_xy * two_g <= tau_peak
                                     ? eps_xy * two_g
                                     : std::max( tau_soft, tau_res );
        ASSERT_NEAR( tau, tau_exact, 1e-10 * tau_peak ) << "step " << step;
        for ( int i : { 0, 1, 3 } )
            ASSERT_NEAR( s[i], -p0, 1e-10 * p0 );
        if ( region == ReturnRegion::Elastic )
            continue;
        ASSERT_EQ( region, ReturnRegion::MainPlane );
        ASSERT_NEAR( yieldRef( m, s, eps ), 0.0, 1e-10 * tau_peak );
        ASSERT_NEAR( eps, 2.0 / std::sqrt( 3.0 ) * ( eps_xy - tau / two_g ),
                     1e-10 * eps );
        // Eq. 14 until eps_p_r, then Eq. 15.
        const bool softening = eps < epsResidual( m );
        ++( softening ? softening_steps : residual_steps );
        ASSERT_NEAR( cohesion( m, eps ),
                     softening ? m.cohesion_peak + m.softening_modulus * eps
                               : m.cohesion_residual,
                     1e-9 );
    }
    EXPECT_GT( softening_steps, 100 );
    EXPECT_GT( residual_steps, 100 );
}

// Plane-strain biaxial test: s_xx = -p0 held (de_xx solved by secant each
// step), axial compression de_yy < 0, de_zz = 0. Major sigma_1 = s_xx = -p0,
// minor sigma_3 = s_yy, intermediate sigma_2 = s_zz = -p0 + nu (s_yy + p0).
// f = 0 gives q = s_xx - s_yy = 2 (c cos(phi) + p0 sin(phi)) / (1 - sin(phi)).
TEST( MohrCoulomb, biaxial_peak_and_residual_match_analytic_strength )
{
    const auto m = testParams( 10.0 );
    const double p0 = 100.0e3;
    const double sin_phi = std::sin( m.friction_angle ),
                 cos_phi = std::cos( m.friction_angle );
    auto strength = [&]( double c )
    { return 2.0 * ( c * cos_phi + p0 * sin_phi ) / ( 1.0 - sin_phi ); };
    const double q_peak = strength( m.cohesion_peak );
    const double q_res = strength( m.cohesion_residual );
    const double two_g = 2.0 * m.shear_modulus;
    const double lambda = m.bulk_modulus - two_g / 3.0;
    const double nu = lambda / ( 2.0 * ( lambda + m.shear_modulus ) );
    // Plane-strain modulus; reach the peak exactly after 400 elastic steps.
    const double e_ps =
        2.0 * two_g * ( lambda + m.shear_modulus ) / ( lambda + two_g );
    const double de_yy = -q_peak / e_ps / 400.0;

    const double s0[4] = { -p0, -p0, 0.0, -p0 };
    double s[4] = { -p0, -p0, 0.0, -p0 }, eps = 0.0, de_xx_guess = 0.0;
    double strain_total[2] = { 0.0, 0.0 }, q_max = 0.0;
    int plastic_steps = 0;
    for ( int step = 0; step < 2400; ++step )
    {
        // Solve s_xx(de_xx) = -p0 by the secant method.
        double s_new[4], eps_new = eps;
        ReturnRegion region = ReturnRegion::Elastic;
        auto residual = [&]( double de_xx )
        {
            const double de[4] = { de_xx, de_yy, 0.0, 0.0 };
            std::copy( s, s + 4, s_new );
            eps_new = eps;
            region = MohrCoulomb{}( m, de, s_new, eps_new );
            return s_new[0] + p0;
        };
        double x0 =
            step == 0 ? -lambda / ( lambda + two_g ) * de_yy : de_xx_guess;
        double r0 = residual( x0 );
        double x1 = x0 - r0 / ( lambda + two_g ), r1 = residual( x1 );
        for ( int it = 0; it < 30 && std::fabs( r1 ) > 1e-7; ++it )
        {
            const double x2 = x1 - r1 * ( x1 - x0 ) / ( r1 - r0 );
            x0 = x1;
            r0 = r1;
            x1 = x2;
            r1 = residual( x1 );
        }
        ASSERT_LE( std::fabs( r1 ), 1e-7 ) << "step " << step;
        std::copy( s_new, s_new + 4, s );
        eps = eps_new;
        de_xx_guess = x1;
        strain_total[0] += x1;
        strain_total[1] += de_yy;

        // Ordering sigma_1 = s_xx >= sigma_2 = s_zz >= sigma_3 = s_yy.
        ASSERT_GE( s[0], s[3] );
        ASSERT_GE( s[3], s[1] );
        ASSERT_NEAR( s[3], -p0 + nu * ( s[1] + p0 ), 1e-9 * p0 );
        const double q = s[0] - s[1];
        q_max = std::max( q_max, q );
        if ( region == ReturnRegion::Elastic )
            continue;
        ++plastic_steps;
        ASSERT_EQ( region, ReturnRegion::MainPlane );
        ASSERT_NEAR( yieldRef( m, s, eps ), 0.0, 1e-10 * q_peak );
        ASSERT_NEAR( q, strength( cohesionRef( m, eps ) ), 1e-10 * q_peak );
        // eps_p_bar from the total plastic strain (proportional loading).
        const auto e_el = plasticStrain( m, s, s0 ); // elastic C : (s - s0)
        const std::array<double, 4> e_p = { strain_total[0] - e_el[0],
                                            strain_total[1] - e_el[1], 0.0,
                                            -e_el[3] };
        ASSERT_NEAR( eps, shearInvariant( e_p ), 1e-8 * eps + 1e-14 );
    }
    EXPECT_GT( plastic_steps, 1000 );
    EXPECT_GT( eps, epsResidual( m ) );
    EXPECT_NEAR( q_max, q_peak, 1e-9 * q_peak );
    EXPECT_NEAR( s[0] - s[1], q_res, 1e-10 * q_res );
}

} // namespace
