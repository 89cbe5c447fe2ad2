#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>

#include <mpm_test_principal.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace
{
using namespace mpm_test::return_mapping;
using Vec = std::array<double, 3>;

using mpm_test::num_regions;

// D x = lambda tr(x) 1 + 2G x and the energy x . C x (C = D^-1), principal.
Vec elastic( const MaterialParams& m, const Vec& x )
{
    const double two_g = 2.0 * m.shear_modulus;
    const double tr = ( m.bulk_modulus - two_g / 3.0 ) * ( x[0] + x[1] + x[2] );
    return { tr + two_g * x[0], tr + two_g * x[1], tr + two_g * x[2] };
}
double energy( const MaterialParams& m, const Vec& x )
{
    const double mean = ( x[0] + x[1] + x[2] ) / 3.0;
    double dev2 = 0.0;
    for ( int i = 0; i < 3; ++i )
        dev2 += ( x[i] - mean ) * ( x[i] - mean );
    return dev2 / ( 2.0 * m.shear_modulus ) +
           9.0 * mean * mean / ( 9.0 * m.bulk_modulus );
}

// Brute-force projection of p_tr onto {f_ij <= 0 (all six ordered faces),
// sigma_i <= sigma_t} in the energy norm, for fixed c: the projections onto
// every intersection of at most three of the nine planes, the nearest of
// those that are admissible. Independent of the ordered-region logic.
Vec closestPoint( const MaterialParams& m, const Vec& p_tr, const double c,
                  const double sigma_t )
{
    const double sp = std::sin( m.friction_angle );
    std::vector<std::pair<Vec, double>> planes; // a . sigma <= r
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 3; ++j )
            if ( i != j )
            {
                Vec a = { 0.0, 0.0, 0.0 };
                a[i] = 1.0 + sp;
                a[j] = -( 1.0 - sp );
                planes.push_back(
                    { a, 2.0 * c * std::cos( m.friction_angle ) } );
            }
    for ( int i = 0; i < 3; ++i )
    {
        Vec a = { 0.0, 0.0, 0.0 };
        a[i] = 1.0;
        planes.push_back( { a, sigma_t } );
    }
    const double scale =
        std::fabs( p_tr[0] ) + std::fabs( p_tr[1] ) + std::fabs( p_tr[2] ) + c;
    const int np = static_cast<int>( planes.size() );
    Vec best = p_tr;
    double best_e = std::numeric_limits<double>::infinity();
    for ( int mask = 0; mask < ( 1 << np ); ++mask )
    {
        std::vector<int> set;
        for ( int k = 0; k < np; ++k )
            if ( mask & ( 1 << k ) )
                set.push_back( k );
        const int n = static_cast<int>( set.size() );
        if ( n > 3 )
            continue;
        // (a_k . D a_l) g = a_k . p_tr - r_k, Gaussian elimination.
        double a[3][4] = {};
        for ( int k = 0; k < n; ++k )
        {
            const Vec& ak = planes[set[k]].first;
            for ( int l = 0; l < n; ++l )
            {
                const Vec da = elastic( m, planes[set[l]].first );
                a[k][l] = ak[0] * da[0] + ak[1] * da[1] + ak[2] * da[2];
            }
            a[k][3] = ak[0] * p_tr[0] + ak[1] * p_tr[1] + ak[2] * p_tr[2] -
                      planes[set[k]].second;
        }
        bool singular = false;
        for ( int k = 0; k < n && !singular; ++k )
        {
            int piv = k;
            for ( int l = k + 1; l < n; ++l )
                if ( std::fabs( a[l][k] ) > std::fabs( a[piv][k] ) )
                    piv = l;
            std::swap( a[k], a[piv] );
            singular = std::fabs( a[k][k] ) < 1e-9 * m.shear_modulus;
            for ( int l = k + 1; l < n && !singular; ++l )
            {
                const double f = a[l][k] / a[k][k];
                for ( int j = k; j < 4; ++j )
                    a[l][j] -= f * a[k][j];
            }
        }
        if ( singular )
            continue;
        double g[3] = {};
        backSubstitute( a, n, g );
        Vec x = p_tr;
        for ( int k = 0; k < n; ++k )
        {
            const Vec da = elastic( m, planes[set[k]].first );
            for ( int i = 0; i < 3; ++i )
                x[i] -= g[k] * da[i];
        }
        bool admissible = true;
        for ( const auto& [av, r] : planes )
            admissible =
                admissible &&
                av[0] * x[0] + av[1] * x[1] + av[2] * x[2] - r <= 1e-12 * scale;
        const double e =
            energy( m, { p_tr[0] - x[0], p_tr[1] - x[1], p_tr[2] - x[2] } );
        if ( admissible && e < best_e )
        {
            best_e = e;
            best = x;
        }
    }
    std::sort( best.begin(), best.end(), std::greater<double>() );
    return best;
}

// Associated flow (psi = phi), no softening: the return is the closest
// admissible point in the energy norm, in every region (random trials).
TEST( TensionCutoff, associated_return_is_the_closest_point )
{
    std::mt19937 gen( 7 );
    std::uniform_real_distribution<double> normal( -60.0e3, 40.0e3 );
    std::uniform_real_distribution<double> shear( -30.0e3, 30.0e3 );
    int visits[num_regions] = {};
    double worst = 0.0;
    for ( const double sigma_t0 : { 0.0, 4.0e3, 12.0e3 } )
    {
        const auto m = tensionTestParams( 30.0, sigma_t0, 0.0 );
        for ( int n = 0; n < 4000; ++n )
        {
            const double s_tr[4] = { normal( gen ), normal( gen ), shear( gen ),
                                     normal( gen ) };
            double s[4] = { s_tr[0], s_tr[1], s_tr[2], s_tr[3] }, eps = 0.01;
            const auto r = MohrCoulomb{}.returnMap( m, s, eps );
            ++visits[static_cast<int>( r )];
            const auto p_tr = principal( s_tr );
            const auto p = principal( s );
            const Vec x = closestPoint( m, { p_tr[0], p_tr[1], p_tr[2] },
                                        m.cohesion_peak, sigma_t0 );
            const double scale =
                std::fabs( p_tr[0] ) + std::fabs( p_tr[2] ) + m.cohesion_peak;
            for ( int i = 0; i < 3; ++i )
            {
                EXPECT_NEAR( p[i], x[i], 1e-10 * scale )
                    << "region " << int( r );
                worst = std::max( worst, std::fabs( p[i] - x[i] ) / scale );
            }
        }
    }
    for ( int r = 5; r < num_regions; ++r )
        EXPECT_GT( visits[r], 20 ) << "region " << r;
    std::printf( "[ closest point ] max |sigma - brute force| / scale %.2e\n",
                 worst );
}

// The return is the only solution: of the nine sets of planes that can be
// active together (MC main plane and edges, and the six with the tension
// plane), exactly one gives a stress meeting every condition (order,
// f_mc <= 0, f_t <= 0, multipliers >= 0), and it is the one returned.
TEST( TensionCutoff, exactly_one_active_set_satisfies_the_conditions )
{
    namespace Impl = mpm::physics::Impl;
    const Impl::YieldPlane sets[9][3] = { { { 0, 2 } },
                                          { { 0, 2 }, { 0, 1 } },
                                          { { 0, 2 }, { 1, 2 } },
                                          { { 0, -1 } },
                                          { { 0, -1 }, { 1, -1 } },
                                          { { 0, -1 }, { 1, -1 }, { 2, -1 } },
                                          { { 0, 2 }, { 0, -1 } },
                                          { { 0, 2 }, { 0, 1 }, { 0, -1 } },
                                          { { 0, 2 }, { 0, -1 }, { 1, -1 } } };
    const int sizes[9] = { 1, 2, 2, 1, 2, 3, 2, 3, 3 };
    std::mt19937 gen( 3 );
    std::uniform_real_distribution<double> normal( -60.0e3, 40.0e3 );
    std::uniform_real_distribution<double> shear( -30.0e3, 30.0e3 );
    std::uniform_real_distribution<double> strain( 0.0, 0.045 );
    int plastic = 0;
    for ( const double psi_deg : { 0.0, 10.0, 30.0 } )
        for ( const double sigma_t0 : { 0.0, 4.0e3, 12.0e3 } )
            for ( const double h : { 0.0, -250.0e3 } )
            {
                const auto m = tensionTestParams( psi_deg, sigma_t0, h );
                for ( int n = 0; n < 3000; ++n )
                {
                    double s[4] = { normal( gen ), normal( gen ), shear( gen ),
                                    normal( gen ) };
                    const auto p_tr = Impl::principalStress( s );
                    double eps = strain( gen );
                    const double eps_n = eps,
                                 c_n = mpm_test::cohesionRef( m, eps );
                    const auto region = MohrCoulomb{}.returnMap( m, s, eps );
                    if ( region == ReturnRegion::Elastic )
                        continue;
                    ++plastic;
                    const double scale = std::fabs( p_tr.sigma[0] ) +
                                         std::fabs( p_tr.sigma[1] ) +
                                         std::fabs( p_tr.sigma[2] ) + c_n;
                    const auto p = principal( s );
                    int valid = 0;
                    for ( int k = 0; k < 9; ++k )
                    {
                        const auto r_k =
                            static_cast<ReturnRegion>( k < 3 ? k + 1 : k + 2 );
                        double s_k[3], dgamma[3], eps_k;
                        Impl::planeReturn( m, sizes[k], sets[k], p_tr.sigma,
                                           eps_n, s_k, eps_k, dgamma );
                        if ( Impl::violation( m, r_k, sizes[k], s_k, dgamma,
                                              eps_k ) > 1e-12 * scale )
                            continue;
                        ++valid;
                        EXPECT_EQ( region, r_k );
                        for ( int i = 0; i < 3; ++i )
                            EXPECT_NEAR( p[i], s_k[i], 1e-12 * scale );
                        EXPECT_NEAR( eps, eps_k, 1e-12 * eps );
                    }
                    ASSERT_EQ( valid, 1 ) << "region " << int( region );
                }
            }
    EXPECT_GT( plastic, 40000 );
}

// Plane-strain uniaxial extension (de_xx only) from zero stress: elastic up
// to s_xx = sigma_t0, then the tension plane with s_xx = sigma_t(eps_p_bar)
// and no plastic strain in yy, zz, so eps_p_bar = 2/3 eps_p_xx. Without
// softening s_xx stays at sigma_t0 and s_yy = s_zz = nu / (1 - nu) sigma_t0;
// with softening s_xx falls to the residual sigma_t0 c_r / c0.
TEST( TensionCutoff, uniaxial_extension_stays_on_the_tension_plane )
{
    const double sigma_t0 = 4.0e3;
    for ( const double h : { 0.0, -250.0e3 } )
    {
        const auto m = tensionTestParams( 10.0, sigma_t0, h );
        const double two_g = 2.0 * m.shear_modulus;
        const double lambda = m.bulk_modulus - two_g / 3.0;
        const double de[4] = { 1.0e-4, 0.0, 0.0, 0.0 };
        const double s0[4] = { 0.0, 0.0, 0.0, 0.0 };
        double s[4] = { 0.0, 0.0, 0.0, 0.0 }, eps = 0.0, strain_xx = 0.0;
        int plastic = 0;
        for ( int step = 0; step < 600; ++step )
        {
            const ReturnRegion region = MohrCoulomb{}( m, de, s, eps );
            strain_xx += de[0];
            ASSERT_NEAR( s[1], s[3], 1e-12 * sigma_t0 );
            ASSERT_EQ( s[2], 0.0 );
            if ( region == ReturnRegion::Elastic )
            {
                ASSERT_NEAR( s[0], ( lambda + two_g ) * strain_xx,
                             1e-9 * sigma_t0 );
                continue;
            }
            ++plastic;
            ASSERT_EQ( region, ReturnRegion::TensionPlane ) << step;
            ASSERT_NEAR( s[0], tensileRef( m, eps ), 1e-12 * sigma_t0 );
            const auto e_el = plasticStrain( m, s, s0 ); // C : (s - s0)
            const std::array<double, 4> e_p = { strain_xx - e_el[0], -e_el[1],
                                                0.0, -e_el[3] };
            ASSERT_NEAR( e_p[1], 0.0, 1e-12 );
            ASSERT_NEAR( eps, 2.0 / 3.0 * e_p[0], 1e-10 * eps );
            ASSERT_NEAR( eps, shearInvariant( e_p ), 1e-10 * eps );
            if ( h == 0.0 )
            {
                ASSERT_NEAR( s[0], sigma_t0, 1e-12 * sigma_t0 );
                ASSERT_NEAR( s[1], lambda / ( lambda + two_g ) * sigma_t0,
                             1e-12 * sigma_t0 );
            }
        }
        EXPECT_GT( plastic, 500 );
        if ( h < 0.0 )
        {
            EXPECT_NEAR( s[0], sigma_t0 * 0.2, 1e-12 * sigma_t0 ); // c_r / c0
        }
    }
}

//! Applies the strain increment `de` 200 times to the stress `s` (and
//! eps_p_bar `eps`), asserting that each plastic step returns onto `region`
//! and then passes `check`; `plastic` counts the plastic steps.
template <class Check>
void runPlasticSteps( const MaterialParams& m, const double de[4], double s[4],
                      double& eps, const ReturnRegion region,
                      const Check& check, int& plastic )
{
    plastic = 0;
    for ( int step = 0; step < 200; ++step )
    {
        const ReturnRegion returned = MohrCoulomb{}( m, de, s, eps );
        if ( returned == ReturnRegion::Elastic )
            continue;
        ++plastic;
        ASSERT_EQ( returned, region ) << step;
        check();
        if ( ::testing::Test::HasFatalFailure() )
            return;
    }
}

// Hydrostatic extension: the trial passes sigma_1 = sigma_2 = sigma_3 =
// sigma_t0 and returns to that corner, with no deviatoric plastic strain
// (eps_p_bar and hence sigma_t unchanged, even with softening).
TEST( TensionCutoff, hydrostatic_extension_reaches_the_tension_apex )
{
    const double sigma_t0 = 4.0e3;
    const auto m = tensionTestParams( 10.0, sigma_t0 );
    const double de[4] = { 2.0e-5, 2.0e-5, 0.0, 2.0e-5 };
    double s[4] = { -10.0e3, -10.0e3, 0.0, -10.0e3 }, eps = 0.0;
    const auto at_the_apex = [&]
    {
        for ( int i : { 0, 1, 3 } )
            ASSERT_NEAR( s[i], sigma_t0, 1e-12 * sigma_t0 );
        ASSERT_NEAR( eps, 0.0, 1e-15 );
    };
    int plastic = 0;
    ASSERT_NO_FATAL_FAILURE( runPlasticSteps(
        m, de, s, eps, ReturnRegion::TensionApex, at_the_apex, plastic ) );
    EXPECT_GT( plastic, 150 );
}

// Plane-strain biaxial extension (de_xx = de_yy, de_zz = 0) from zero stress:
// s_xx = s_yy reach sigma_t0 together and stay on the tension edge, with
// s_zz = lambda / (lambda + G) sigma_t0 (no softening).
TEST( TensionCutoff, biaxial_extension_reaches_the_tension_edge )
{
    const double sigma_t0 = 4.0e3;
    const auto m = tensionTestParams( 10.0, sigma_t0, 0.0 );
    const double lambda = m.bulk_modulus - 2.0 / 3.0 * m.shear_modulus;
    const double de[4] = { 1.0e-5, 1.0e-5, 0.0, 0.0 };
    double s[4] = { 0.0, 0.0, 0.0, 0.0 }, eps = 0.0;
    const auto on_the_edge = [&]
    {
        ASSERT_NEAR( s[0], sigma_t0, 1e-12 * sigma_t0 );
        ASSERT_NEAR( s[1], sigma_t0, 1e-12 * sigma_t0 );
        ASSERT_NEAR( s[3], lambda / ( lambda + m.shear_modulus ) * sigma_t0,
                     1e-12 * sigma_t0 );
    };
    int plastic = 0;
    ASSERT_NO_FATAL_FAILURE( runPlasticSteps(
        m, de, s, eps, ReturnRegion::TensionEdge, on_the_edge, plastic ) );
    EXPECT_GT( plastic, 150 );
    // Plastic strain (1, 1, 0) per unit: eps_p_bar = 2/3 of each component.
    EXPECT_GT( eps, 0.0 );
}

} // namespace
