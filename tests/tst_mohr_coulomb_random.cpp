// Mohr-Coulomb returns of random trials in every region.
#include <mpm_test_mohr_coulomb.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace
{
using namespace mpm_test::mohr_coulomb;

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
