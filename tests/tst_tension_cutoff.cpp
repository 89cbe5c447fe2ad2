#include <io/mpm_case_reader.hpp>
#include <mpm_test_minimal_case.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>
#include <setup/mpm_materials.hpp>

#include <mpm_test_principal.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace mpm_test::return_mapping;

const double pi = std::acos( -1.0 );
const double inf = std::numeric_limits<double>::infinity();
using mpm_test::num_regions;

// Yield functions of sorted principal stresses p: MC f_13 and tension
// f_t = s1 - sigma_t, and a stress scale for the tolerances.
struct Yield
{
    double mc, t, scale;
};
Yield yieldRef( const MaterialParams& m, const std::array<double, 3>& p,
                const double eps )
{
    const double sin_phi = std::sin( m.friction_angle );
    const double c = cohesionRef( m, eps );
    const double two_c_cos = 2.0 * c * std::cos( m.friction_angle );
    return { ( p[0] - p[2] ) + ( p[0] + p[2] ) * sin_phi - two_c_cos,
             p[0] - tensileRef( m, eps ),
             two_c_cos + std::fabs( p[0] ) + std::fabs( p[1] ) +
                 std::fabs( p[2] ) };
}

// Flow directions (principal, sorted order) of the planes active in a region:
// MC faces b_ij = (1 + sin psi) e_i - (1 - sin psi) e_j, Rankine e_i.
std::vector<std::array<double, 3>> flowDirections( const ReturnRegion r,
                                                   const double sp )
{
    const std::array<double, 3> b13 = { 1.0 + sp, 0.0, -( 1.0 - sp ) },
                                b12 = { 1.0 + sp, -( 1.0 - sp ), 0.0 },
                                b23 = { 0.0, 1.0 + sp, -( 1.0 - sp ) },
                                e1 = { 1.0, 0.0, 0.0 }, e2 = { 0.0, 1.0, 0.0 },
                                e3 = { 0.0, 0.0, 1.0 };
    switch ( r )
    {
    case ReturnRegion::MainPlane:
        return { b13 };
    case ReturnRegion::RightEdge:
        return { b13, b12 };
    case ReturnRegion::LeftEdge:
        return { b13, b23 };
    case ReturnRegion::TensionPlane:
        return { e1 };
    case ReturnRegion::TensionEdge:
        return { e1, e2 };
    case ReturnRegion::TensionApex:
        return { e1, e2, e3 };
    case ReturnRegion::MainPlaneTension:
        return { b13, e1 };
    case ReturnRegion::RightTensionCorner:
        return { b13, b12, e1 };
    case ReturnRegion::LeftTensionCorner:
        return { b13, b23, e1, e2 };
    default:
        return {};
    }
}

// Plastic strain d (principal) as sum_k g_k b_k: smallest g_k and residual
// |d - sum g_k b_k| (least squares; the left tension corner has four
// directions: g_13 + g_23 = -d3 / (1 - sp) is split as favourably as possible).
std::array<double, 2> flowFit( const ReturnRegion r, const double sp,
                               const std::array<double, 3>& d )
{
    auto b = flowDirections( r, sp );
    if ( r == ReturnRegion::LeftTensionCorner )
    {
        const double g = -d[2] / ( 1.0 - sp ); // g_13 + g_23
        // Best split: g_1 = d1 - g_13 (1 + sp), g_2 = d2 - g_23 (1 + sp).
        const double lo = std::max( 0.0, g - d[1] / ( 1.0 + sp ) );
        const double hi = std::min( g, d[0] / ( 1.0 + sp ) );
        const double g13 = std::clamp( 0.5 * ( lo + hi ), 0.0, g );
        const double mins[4] = { g13, g - g13, d[0] - g13 * ( 1.0 + sp ),
                                 d[1] - ( g - g13 ) * ( 1.0 + sp ) };
        return { *std::min_element( mins, mins + 4 ), 0.0 };
    }
    const int n = static_cast<int>( b.size() );
    // Normal equations (B^T B) g = B^T d, Gaussian elimination.
    double a[3][4] = {};
    for ( int k = 0; k < n; ++k )
    {
        for ( int l = 0; l < n; ++l )
            for ( int i = 0; i < 3; ++i )
                a[k][l] += b[k][i] * b[l][i];
        for ( int i = 0; i < 3; ++i )
            a[k][3] += b[k][i] * d[i];
    }
    for ( int k = 0; k < n; ++k )
        for ( int l = k + 1; l < n; ++l )
        {
            const double f = a[l][k] / a[k][k];
            for ( int j = k; j < 4; ++j )
                a[l][j] -= f * a[k][j];
        }
    double g[3] = {};
    backSubstitute( a, n, g );
    double g_min = inf, res2 = 0.0;
    for ( int k = 0; k < n; ++k )
        g_min = std::min( g_min, g[k] );
    for ( int i = 0; i < 3; ++i )
    {
        double fit = 0.0;
        for ( int k = 0; k < n; ++k )
            fit += g[k] * b[k][i];
        res2 += ( d[i] - fit ) * ( d[i] - fit );
    }
    return { g_min, std::sqrt( res2 ) };
}

// Return from s_tr with the checks every return must pass: f_mc <= 0 and
// f_t <= 0, = 0 for the active ones, the equal principal stresses of an edge
// or corner, coaxiality, eps_p_bar += sqrt(2/3 de_p : de_p), and de_p a
// non-negative combination of the region's flow directions. Records the
// largest |f| of the active surfaces per region in worst[].
ReturnRegion checkedReturn( const MaterialParams& m, const double s_tr[4],
                            const double eps_n, double s[4], double& eps,
                            double* worst = nullptr )
{
    std::copy( s_tr, s_tr + 4, s );
    eps = eps_n;
    const ReturnRegion region = MohrCoulomb{}.returnMap( m, s, eps );
    const auto p_tr = principal( s_tr );
    const Yield y_tr = yieldRef( m, p_tr, eps_n );
    EXPECT_EQ( region == ReturnRegion::Elastic,
               y_tr.mc <= 0.0 && y_tr.t <= 0.0 )
        << "f_tr " << y_tr.mc << ", " << y_tr.t;
    if ( region == ReturnRegion::Elastic )
        return region;
    EXPECT_NE( region, ReturnRegion::Apex ); // above sigma_t: cut off
    const auto p = principal( s );
    const Yield y = yieldRef( m, p, eps );
    const double tol = 1e-10 * y.scale;
    const int r = static_cast<int>( region );
    const bool mc_active = r <= 4 || r >= 8, t_active = r >= 5;
    EXPECT_LE( y.mc, tol );
    EXPECT_LE( y.t, tol );
    if ( mc_active )
    {
        EXPECT_NEAR( y.mc, 0.0, tol );
    }
    if ( t_active )
    {
        EXPECT_NEAR( y.t, 0.0, tol );
    }
    if ( worst )
        worst[r] = std::max(
            { worst[r], ( mc_active ? std::fabs( y.mc ) : 0.0 ) / y.scale,
              ( t_active ? std::fabs( y.t ) : 0.0 ) / y.scale } );
    // Equal principal stresses on edges and corners.
    const bool eq12 = region == ReturnRegion::LeftEdge ||
                      region == ReturnRegion::TensionEdge ||
                      region == ReturnRegion::TensionApex ||
                      region == ReturnRegion::LeftTensionCorner;
    const bool eq23 = region == ReturnRegion::RightEdge ||
                      region == ReturnRegion::TensionApex ||
                      region == ReturnRegion::RightTensionCorner;
    if ( eq12 )
    {
        EXPECT_NEAR( p[0], p[1], tol );
    }
    if ( eq23 )
    {
        EXPECT_NEAR( p[1], p[2], tol );
    }
    // Coaxial: the 2x2 commutator of s and s_tr vanishes.
    EXPECT_NEAR( ( s[0] - s[1] ) * s_tr[2] - ( s_tr[0] - s_tr[1] ) * s[2], 0.0,
                 1e-10 * y_tr.scale * y_tr.scale );
    // eps_p_bar from the plastic strain C : (s_tr - s).
    const auto de_p = plasticStrain( m, s_tr, s );
    const double d_eps = softeningIncrementRef( m, de_p );
    EXPECT_GE( eps, eps_n );
    EXPECT_NEAR( eps - eps_n, d_eps, 1e-9 * d_eps + 1e-16 );
    // Flow rule in the trial's principal order: C (p_tr - p).
    const double two_g = 2.0 * m.shear_modulus, k9 = 9.0 * m.bulk_modulus;
    const double ds_mean =
        ( p_tr[0] - p[0] + p_tr[1] - p[1] + p_tr[2] - p[2] ) / 3.0;
    std::array<double, 3> d;
    double d_max = 0.0;
    for ( int i = 0; i < 3; ++i )
    {
        d[i] = ( p_tr[i] - p[i] - ds_mean ) / two_g + 3.0 * ds_mean / k9;
        d_max = std::max( d_max, std::fabs( d[i] ) );
    }
    const auto fit = flowFit( region, std::sin( m.dilation_angle ), d );
    EXPECT_GE( fit[0], -1e-9 * d_max ) << "region " << r;
    EXPECT_NEAR( fit[1], 0.0, 1e-9 * d_max ) << "region " << r;
    return region;
}

TEST( TensionCutoff, cutoff_only_below_the_apex )
{
    auto m = tensionTestParams( 10.0, inf );
    EXPECT_FALSE( m.tension_cutoff );
    m.setTensileStrength( 4.0e3 );
    EXPECT_TRUE( m.tension_cutoff );
    EXPECT_DOUBLE_EQ( m.tensile_ratio, 0.4 );
    const double apex = 10.0e3 / std::tan( 30.0 * pi / 180.0 );
    for ( const double at_or_above : { apex, 1.01 * apex, inf } )
    {
        m.setTensileStrength( at_or_above );
        EXPECT_FALSE( m.tension_cutoff ) << at_or_above;
    }
    m.setTensileStrength( 0.0 );
    EXPECT_TRUE( m.tension_cutoff );
    m.cohesion_peak = 0.0; // apex 0: sigma_t0 = 0 is no cut-off
    m.setTensileStrength( 0.0 );
    EXPECT_FALSE( m.tension_cutoff );
}

// A cut-off at or above the apex returns bit for bit what no cut-off (the
// default) returns, on the random trials of tst_mohr_coulomb.cpp, and never
// a tension region. (At the merge, 180,000 such trials were also bit for
// bit those of the Mohr-Coulomb code before the cut-off.)
TEST( TensionCutoff, no_cutoff_is_bit_identical_to_mohr_coulomb_alone )
{
    std::mt19937 gen( 20180801 );
    std::uniform_real_distribution<double> normal( -300.0e3, 60.0e3 );
    std::uniform_real_distribution<double> shear( -80.0e3, 80.0e3 );
    std::uniform_real_distribution<double> strain( 0.0, 0.045 );
    const double apex = 10.0e3 / std::tan( 30.0 * pi / 180.0 );
    EXPECT_FALSE( MaterialParams{}.tension_cutoff ); // none by default
    int plastic = 0;
    for ( const double psi_deg : { 0.0, 10.0, 30.0 } )
    {
        const auto plain = tensionTestParams( psi_deg, inf );
        ASSERT_FALSE( plain.tension_cutoff );
        for ( const double sigma_t0 : { inf, apex, 2.0 * apex } )
        {
            const auto m = tensionTestParams( psi_deg, sigma_t0 );
            ASSERT_FALSE( m.tension_cutoff );
            for ( int n = 0; n < 20000; ++n )
            {
                const double s_tr[4] = { normal( gen ), normal( gen ),
                                         shear( gen ), normal( gen ) };
                double s[4], s_ref[4];
                std::copy( s_tr, s_tr + 4, s );
                std::copy( s_tr, s_tr + 4, s_ref );
                double eps = strain( gen ), eps_ref = eps;
                const auto r = MohrCoulomb{}.returnMap( m, s, eps );
                const auto r_ref =
                    MohrCoulomb{}.returnMap( plain, s_ref, eps_ref );
                ASSERT_EQ( static_cast<int>( r ), static_cast<int>( r_ref ) );
                ASSERT_EQ( std::memcmp( s, s_ref, sizeof s ), 0 ) << n;
                ASSERT_EQ( std::memcmp( &eps, &eps_ref, sizeof eps ), 0 ) << n;
                EXPECT_LT( static_cast<int>( r ),
                           static_cast<int>( ReturnRegion::TensionPlane ) );
                plastic += r != ReturnRegion::Elastic;
            }
        }
    }
    EXPECT_GT( plastic, 100000 );
}

// Random trials, rotated (xy != 0), over the tension side: every return
// passes checkedReturn; every region but the apex is visited.
TEST( TensionCutoff, random_trials_satisfy_consistency_in_every_region )
{
    std::mt19937 gen( 20260212 );
    std::uniform_real_distribution<double> normal( -60.0e3, 40.0e3 );
    std::uniform_real_distribution<double> shear( -30.0e3, 30.0e3 );
    std::uniform_real_distribution<double> strain( 0.0, 0.045 );
    int visits[num_regions] = {};
    double worst[num_regions] = {};
    for ( const auto measure : { SofteningMeasure::EquivalentPlasticStrain,
                                 SofteningMeasure::EngineeringShearStrain } )
        for ( const double psi_deg : { 0.0, 10.0, 30.0 } )
            for ( const double sigma_t0 : { 0.0, 4.0e3, 12.0e3 } )
            {
                auto m = tensionTestParams( psi_deg, sigma_t0 );
                m.softening_measure = measure;
                ASSERT_TRUE( m.tension_cutoff );
                for ( int n = 0; n < 10000; ++n )
                {
                    const double s_tr[4] = { normal( gen ), normal( gen ),
                                             shear( gen ), normal( gen ) };
                    double s[4], eps;
                    const auto r =
                        checkedReturn( m, s_tr, strain( gen ), s, eps, worst );
                    ++visits[static_cast<int>( r )];
                }
            }
    for ( int r = 0; r < num_regions; ++r )
    {
        if ( r == static_cast<int>( ReturnRegion::Apex ) )
        {
            EXPECT_EQ( visits[r], 0 );
        }
        else
        {
            EXPECT_GT( visits[r], 100 ) << "region " << r;
        }
        std::printf( "[ region %2d ] %6d returns, max |f| / scale %.2e\n", r,
                     visits[r], worst[r] );
    }
}

//---------------------------------------------------------------------------//
// Case reader: tensile_strength_pa (the bad values are in data/bad_cases:
// negative, nan, above the apex, apex lowered by a stage override).
//---------------------------------------------------------------------------//
using mpm_test::minimal_case;

// The case with tensile_strength_pa = value after friction_angle_deg.
std::string withTensileStrength( const std::string& value )
{
    std::string text = minimal_case;
    const std::string key = "friction_angle_deg = 30.0";
    text.insert( text.find( key ) + key.size(),
                 "\ntensile_strength_pa = " + value );
    return text;
}

TEST( CaseReader, tensile_strength_is_read_and_defaults_to_none )
{
    const auto none = mpm::parseCase( minimal_case, "none.toml" );
    EXPECT_EQ( none.materials[0].tensile_strength_pa, inf );
    EXPECT_FALSE( mpm::makeMaterialTable( none.materials )[0].tension_cutoff );

    const auto c = mpm::parseCase( withTensileStrength( "5.0e3" ), "t.toml" );
    EXPECT_DOUBLE_EQ( c.materials[0].tensile_strength_pa, 5.0e3 );
    const auto table = mpm::makeMaterialTable( c.materials );
    EXPECT_TRUE( table[0].tension_cutoff );
    EXPECT_DOUBLE_EQ( table[0].tensile_strength, 5.0e3 );
    EXPECT_DOUBLE_EQ( table[0].tensile_ratio, 0.5 );

    // At the apex c0 cot(phi) (shortest exact text): accepted, no cut-off.
    char apex[40];
    std::snprintf( apex, sizeof apex, "%.17g",
                   10.0e3 / std::tan( 30.0 * M_PI / 180.0 ) );
    const auto at_apex =
        mpm::parseCase( withTensileStrength( apex ), "a.toml" );
    EXPECT_FALSE(
        mpm::makeMaterialTable( at_apex.materials )[0].tension_cutoff );
}

TEST( CaseReader, tensile_strength_above_apex_or_negative_is_rejected )
{
    const std::pair<const char*, const char*> bad[] = {
        { "17400.0", "key 'materials[0].tensile_strength_pa': expected a "
                     "number in [0, 17320.508075688773] Pa (at most the apex" },
        { "-1.0", "key 'materials[0].tensile_strength_pa': expected a number "
                  ">= 0 Pa, found -1.0" },
        { "nan", "expected a number >= 0 Pa, found nan" },
        { "inf", "expected a number >= 0 Pa, found inf" } };
    for ( const auto& [value, message] : bad )
    {
        try
        {
            mpm::parseCase( withTensileStrength( value ), "bad.toml" );
            ADD_FAILURE() << "accepted " << value;
        }
        catch ( const mpm::CaseError& e )
        {
            EXPECT_NE( std::string( e.what() ).find( message ),
                       std::string::npos )
                << e.what();
        }
    }
}

} // namespace

//---------------------------------------------------------------------------//
// Case reader: softening_measure (the bad ones are in data/bad_cases:
// misspelt, on a linear elastic stage override).
//---------------------------------------------------------------------------//
TEST( CaseReader, softening_measure_is_read_and_defaults_to_eps_p_bar )
{
    const auto plain = mpm::parseCase( minimal_case, "plain.toml" );
    EXPECT_EQ( mpm::makeMaterialTable( plain.materials )[0].softening_measure,
               SofteningMeasure::EquivalentPlasticStrain );

    std::string text = minimal_case;
    const std::string key = "friction_angle_deg = 30.0";
    text.insert( text.find( key ) + key.size(),
                 "\nsoftening_measure = \"engineering_shear_strain\"" );
    const auto c = mpm::parseCase( text, "e.toml" );
    EXPECT_EQ( c.materials[0].softening_measure,
               mpm::SofteningMeasureType::EngineeringShearStrain );
    EXPECT_EQ( mpm::makeMaterialTable( c.materials )[0].softening_measure,
               SofteningMeasure::EngineeringShearStrain );
    // Inherited by a stage override of the material.
    EXPECT_EQ( c.stages[0].materials[0].softening_measure,
               mpm::SofteningMeasureType::EngineeringShearStrain );
}
