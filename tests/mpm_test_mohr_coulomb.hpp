#ifndef MPM_TEST_MOHR_COULOMB_HPP
#define MPM_TEST_MOHR_COULOMB_HPP

#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>

#include <mpm_test_principal.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

//---------------------------------------------------------------------------//
// The material, trial stresses and checked return shared by the Mohr-Coulomb
// return tests (tst_mohr_coulomb.cpp, tst_mohr_coulomb_random.cpp).
//---------------------------------------------------------------------------//
namespace mpm_test
{
namespace mohr_coulomb
{
using namespace mpm_test::return_mapping;
using mpm::physics::yieldFunction;

inline const double pi = std::acos( -1.0 );

// E = 10 MPa, nu = 0.3, c0 = 10 kPa, c_r = 2 kPa, H = -250 kPa,
// phi = 30 deg, psi = 10 deg (psi != phi so that swapping them fails).
inline MaterialParams testParams( const double psi_deg = 10.0 )
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
inline double epsResidual( const MaterialParams& m )
{
    return ( m.cohesion_residual - m.cohesion_peak ) / m.softening_modulus;
}

// The MC yield function written out here: f and its scale
// 2c cos(phi) + |s1 + s3| sin(phi) + |s1 - s3|.
inline double yieldRef( const MaterialParams& m, const double s[4],
                        const double eps, double* scale = nullptr )
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
inline const double main_tr[4] = { -30.0e3, -160.0e3, 0.0, -80.0e3 };
inline const double right_tr[4] = { -20.0e3, -155.0e3, 0.0, -150.0e3 };
inline const double left_tr[4] = { -20.0e3, -160.0e3, 0.0, -25.0e3 };
inline const double apex_tr[4] = { 30.0e3, 20.0e3, 4.0e3, 25.0e3 };
inline const ReturnRegion expected[3] = {
    ReturnRegion::MainPlane, ReturnRegion::RightEdge, ReturnRegion::LeftEdge };

// Return from s_tr; checks shared by all plastic returns: f = 0, the eps_p_bar
// increment equals sqrt(2/3 de_p : de_p) (or (de_1 - de_3), with the
// engineering measure) of de_p = C : (s_tr - s).
inline ReturnRegion checkedReturn( const MaterialParams& m,
                                   const double s_tr[4], const double eps_n,
                                   double s[4], double& eps )
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

} // namespace mohr_coulomb
} // namespace mpm_test

#endif // MPM_TEST_MOHR_COULOMB_HPP
