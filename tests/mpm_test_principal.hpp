#ifndef MPM_TEST_PRINCIPAL_HPP
#define MPM_TEST_PRINCIPAL_HPP

#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>

#include <algorithm>
#include <array>
#include <cmath>

//---------------------------------------------------------------------------//
// Reference formulas for the return-mapping tests (tst_mohr_coulomb.cpp,
// tst_tension_cutoff.cpp), written independently of the implementation.
//---------------------------------------------------------------------------//
namespace mpm_test
{
using mpm::physics::MaterialParams;

//! Principal values, descending, of a tensor {xx, yy, xy, zz}.
inline std::array<double, 3> principal( const double t[4] )
{
    const double center = 0.5 * ( t[0] + t[1] );
    const double radius = std::hypot( 0.5 * ( t[0] - t[1] ), t[2] );
    std::array<double, 3> v = { center + radius, center - radius, t[3] };
    std::sort( v.begin(), v.end(), []( double a, double b ) { return a > b; } );
    return v;
}

//! Eq. 14-15 cohesion, Pa.
inline double cohesionRef( const MaterialParams& m, const double eps )
{
    return std::max( m.cohesion_peak + m.softening_modulus * eps,
                     m.cohesion_residual );
}

//! Strain C : (s_a - s_b) as {xx, yy, xy (tensor), zz}; with (s_tr, s) it is
//! the plastic strain increment of a return.
inline std::array<double, 4> plasticStrain( const MaterialParams& m,
                                            const double s_tr[4],
                                            const double s[4] )
{
    double ds[4];
    for ( int i = 0; i < 4; ++i )
        ds[i] = s_tr[i] - s[i];
    const double mean = ( ds[0] + ds[1] + ds[3] ) / 3.0;
    const double g2 = 2.0 * m.shear_modulus, k3 = 3.0 * m.bulk_modulus;
    return { ( ds[0] - mean ) / g2 + mean / k3,
             ( ds[1] - mean ) / g2 + mean / k3, ds[2] / g2,
             ( ds[3] - mean ) / g2 + mean / k3 };
}

//! sqrt( 2/3 dev(e) : dev(e) ), the xy component counted twice.
inline double shearInvariant( const std::array<double, 4>& e )
{
    const double mean = ( e[0] + e[1] + e[3] ) / 3.0;
    const double dd = ( e[0] - mean ) * ( e[0] - mean ) +
                      ( e[1] - mean ) * ( e[1] - mean ) +
                      ( e[3] - mean ) * ( e[3] - mean ) + 2.0 * e[2] * e[2];
    return std::sqrt( 2.0 / 3.0 * dd );
}

//! Increment of the material's softening measure for the plastic strain
//! increment de_p: sqrt( 2/3 dev : dev ) or ( de_1 - de_3 ), principal.
inline double softeningIncrementRef( const MaterialParams& m,
                                     const std::array<double, 4>& de_p )
{
    if ( m.softening_measure ==
         mpm::physics::SofteningMeasure::EngineeringShearStrain )
    {
        const auto d = principal( de_p.data() );
        return d[0] - d[2];
    }
    return shearInvariant( de_p );
}

//! Number of ReturnRegion values (Elastic ... LeftTensionCorner).
constexpr int num_regions = 11;

//! The tests' Mohr-Coulomb soil (E = 10 MPa, nu = 0.3, c0 = 10 kPa, c_r =
//! 2 kPa, phi = 30 deg) with dilation psi, softening H (Pa) and tension
//! cut-off sigma_t0 (Pa; apex c0 cot(phi) = 17.3 kPa; infinity: none).
inline MaterialParams tensionTestParams( const double psi_deg = 10.0,
                                         const double sigma_t0 = 4.0e3,
                                         const double h = -250.0e3 )
{
    const double deg = std::acos( -1.0 ) / 180.0;
    MaterialParams m = mpm::physics::elasticParams( 1.0e7, 0.3, 2000.0 );
    m.model = mpm::physics::Model::MohrCoulomb;
    m.cohesion_peak = 10.0e3;
    m.cohesion_residual = 2.0e3;
    m.softening_modulus = h;
    m.setAngles( 30.0 * deg, psi_deg * deg );
    m.setTensileStrength( sigma_t0 );
    return m;
}

//! Tensile strength sigma_t = sigma_t0 c / c0 (softened with the cohesion).
inline double tensileRef( const MaterialParams& m, const double eps )
{
    return m.tensile_strength * cohesionRef( m, eps ) / m.cohesion_peak;
}

//! Solves the upper triangular n x n system of the rows a[k] = (A_k | b_k)
//! (after a forward elimination) for g.
inline void backSubstitute( const double a[3][4], const int n, double g[3] )
{
    for ( int k = n - 1; k >= 0; --k )
    {
        g[k] = a[k][3];
        for ( int l = k + 1; l < n; ++l )
            g[k] -= a[k][l] * g[l];
        g[k] /= a[k][k];
    }
}

//! The names the return-mapping tests use
//! (`using namespace mpm_test::return_mapping;`).
namespace return_mapping
{
using mpm::physics::cohesion;
using mpm::physics::MaterialParams;
using mpm::physics::MohrCoulomb;
using mpm::physics::ReturnRegion;
using mpm::physics::SofteningMeasure;
using mpm_test::backSubstitute;
using mpm_test::cohesionRef;
using mpm_test::plasticStrain;
using mpm_test::principal;
using mpm_test::shearInvariant;
using mpm_test::softeningIncrementRef;
using mpm_test::tensileRef;
using mpm_test::tensionTestParams;
} // namespace return_mapping

} // namespace mpm_test

#endif // MPM_TEST_PRINCIPAL_HPP
