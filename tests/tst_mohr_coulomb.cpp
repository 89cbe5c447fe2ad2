#include <mpm_test_mohr_coulomb.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
using namespace mpm_test::mohr_coulomb;

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

} // namespace
