#include <mpm_test_retention.hpp>
#include <physics/mpm_retention.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using mpm::physics::Retention;
using mpm::physics::RetentionModel;
using mpm::physics::RetentionParams;
using mpm::physics::RetentionState;

using mpm_test::retentionParams;

// The paper's slope (Sec. 3): alpha = 0.44 1/kPa, n = 3.04, S_res = 0.23.
RetentionParams slopeVanGenuchten()
{
    auto r = retentionParams( RetentionModel::VanGenuchten, 0.23, 1.0 );
    r.alpha_per_pa = 4.4e-4;
    r.n_vg = 3.04;
    return r;
}

RetentionParams liakopoulosParams( const double s_res, const double k_min )
{
    auto r = retentionParams( RetentionModel::Liakopoulos, s_res, 1.0 );
    r.k_rel_min = k_min;
    return r;
}

RetentionParams gardnerParams()
{
    auto r = retentionParams( RetentionModel::Gardner, 0.1, 0.9 );
    r.alpha_per_m = 0.5;
    r.rho_w_g = 9810.0;
    return r;
}

RetentionParams linearParams()
{
    auto r = retentionParams( RetentionModel::Linear, 0.2, 1.0 );
    r.suction_range_pa = 1.0e4;
    return r;
}

// Independent textbook van Genuchten-Mualem in long double (Eqs. 16-19).
void referenceVanGenuchten( const RetentionParams& r, const double s,
                            long double& S, long double& k_rel )
{
    const long double n = r.n_vg;
    const long double m = 1.0L - 1.0L / n;
    const long double s_e =
        std::pow( 1.0L + std::pow( (long double)r.alpha_per_pa * s, n ), -m );
    const long double inner =
        1.0L - std::pow( 1.0L - std::pow( s_e, n / ( n - 1.0L ) ), m );
    S = r.s_res + ( r.s_sat - r.s_res ) * s_e;
    k_rel = std::sqrt( s_e ) * inner * inner;
}

// Pore pressures from +10 kPa down to -10 MPa (log-spaced suctions).
std::vector<double> pressureSweep()
{
    std::vector<double> p = { 1.0e4, 1.0, 0.0 };
    for ( int i = 0; i <= 400; ++i )
        p.push_back( -std::pow( 10.0, -2.0 + 9.0 * i / 400.0 ) );
    return p;
}

//---------------------------------------------------------------------------//
TEST( Retention, van_genuchten_matches_verification_values )
{
    // verification.md 5.2: alpha in 1/kPa; 0.44 1/Pa would give S ~ s_res.
    const auto r = slopeVanGenuchten();
    const Retention ret;
    // Hand values to 1e-12 from the formula (mpmath, 40 digits).
    const double s[4] = { 50.0e3, 5.0e3, 2.0e3, 1.0e3 };
    const double S_verif[4] = { 0.2314, 0.375, 0.774, 0.960 };
    const double S_exact[4] = { 0.23140580236835229, 0.37540067171128262,
                                0.77405666366673633, 0.96013989893559915 };
    for ( int i = 0; i < 4; ++i )
    {
        EXPECT_NEAR( ret( r, -s[i] ).S, S_verif[i], 1e-3 );
        EXPECT_NEAR( ret( r, -s[i] ).S, S_exact[i], 1e-12 );
    }
    // S_e(50 kPa) = 1.83e-3.
    EXPECT_NEAR( ( ret( r, -50.0e3 ).S - 0.23 ) / 0.77, 1.83e-3, 1e-5 );
    EXPECT_NEAR( ret.saturation( r, -2.0e3 ), 0.77405666366673633, 1e-12 );
}

TEST( Retention, van_genuchten_mualem_krel_at_initial_suction )
{
    const auto r = slopeVanGenuchten();
    const Retention ret;
    const double k = ret( r, -50.0e3 ).k_rel;
    EXPECT_NEAR( k, 1.3e-10, 0.05 * 1.3e-10 );
    // 40-digit value and the independent long-double implementation.
    EXPECT_NEAR( k, 1.3250730275075449e-10, 1e-10 * 1.325e-10 );
    long double S_ref, k_ref;
    referenceVanGenuchten( r, 50.0e3, S_ref, k_ref );
    EXPECT_NEAR( k, (double)k_ref, 1e-10 * (double)k_ref );
    // Hand values at the wet end (the Mualem square matters: 0.1745 vs 0.418).
    EXPECT_NEAR( ret( r, -2.0e3 ).k_rel, 0.17449864712709292, 1e-13 );
    EXPECT_NEAR( ret( r, -1.0e3 ).k_rel, 0.6585273773201308, 1e-13 );
    EXPECT_NEAR( ret( r, -100.0 ).k_rel, 0.99656073025618475, 1e-13 );
}

TEST( Retention, van_genuchten_krel_matches_independent_implementation )
{
    // Long double textbook formula is accurate to < 1e-11 for 25 Pa..1 MPa.
    const auto r = slopeVanGenuchten();
    const Retention ret;
    for ( int i = 0; i <= 200; ++i )
    {
        const double s = 25.0 * std::pow( 4.0e4, i / 200.0 );
        long double S_ref, k_ref;
        referenceVanGenuchten( r, s, S_ref, k_ref );
        SCOPED_TRACE( s );
        const RetentionState st = ret( r, -s );
        EXPECT_NEAR( st.S, (double)S_ref, 1e-14 );
        EXPECT_NEAR( st.k_rel, (double)k_ref, 1e-9 * (double)k_ref );
        // k_rel(S) agrees with the p_w form.
        EXPECT_NEAR( ret.relativePermeability( r, st.S ), st.k_rel,
                     1e-8 * st.k_rel );
    }
}

TEST( Retention, van_genuchten_is_robust_at_both_ends )
{
    auto r = slopeVanGenuchten();
    const Retention ret;
    // Near S_e = 1: 1 - k_rel ~ 2 (alpha s)^(n-1) to leading order; here
    // (alpha s)^n = 6e-19, so the textbook formula gives k_rel = 1 exactly.
    const double x = 1.0e-6;
    const RetentionState wet = ret( r, -x / r.alpha_per_pa );
    EXPECT_NEAR( 1.0 - wet.k_rel, 2.0 * std::pow( x, r.n_vg - 1.0 ),
                 1e-3 * 2.0 * std::pow( x, r.n_vg - 1.0 ) );
    for ( const double p : { -1.0e-300, -1.0e-30, -1.0e12, -1.0e300 } )
    {
        const RetentionState st = ret( r, p );
        EXPECT_TRUE( std::isfinite( st.S ) && std::isfinite( st.dS_dp ) &&
                     std::isfinite( st.k_rel ) )
            << "p_w = " << p;
        EXPECT_GE( st.S, r.s_res );
        EXPECT_LE( st.S, r.s_sat );
        EXPECT_GE( st.dS_dp, 0.0 );
        EXPECT_GE( st.k_rel, 0.0 );
        EXPECT_LE( st.k_rel, 1.0 );
    }
    EXPECT_DOUBLE_EQ( ret( r, -1.0e-30 ).S, 1.0 );
    EXPECT_NEAR( ret( r, -1.0e12 ).S, r.s_res, 1e-12 );
    EXPECT_EQ( ret.relativePermeability( r, r.s_res ), 0.0 );
    EXPECT_EQ( ret.relativePermeability( r, 1.0 ), 1.0 );
    // Floor.
    r.k_rel_min = 1.0e-6;
    EXPECT_EQ( ret( r, -50.0e3 ).k_rel, 1.0e-6 );
    EXPECT_EQ( ret.relativePermeability( r, 0.2314 ), 1.0e-6 );
}

TEST( Retention, saturated_at_non_negative_pressure )
{
    const Retention ret;
    RetentionParams sat;
    for ( const auto& r : { slopeVanGenuchten(), liakopoulosParams( 0.2, 1e-4 ),
                            gardnerParams(), linearParams(), sat } )
    {
        for ( const double p : { 0.0, -0.0, 1.0, 1.0e5 } )
        {
            const RetentionState st = ret( r, p );
            EXPECT_EQ( st.S, r.model == RetentionModel::Saturated ||
                                     r.model == RetentionModel::Liakopoulos
                                 ? 1.0
                                 : r.s_sat );
            EXPECT_EQ( st.dS_dp, 0.0 );
            EXPECT_EQ( st.k_rel, 1.0 );
            EXPECT_EQ( ret.saturation( r, p ), st.S );
        }
    }
    // Saturated law ignores suction.
    const RetentionState st = ret( sat, -1.0e6 );
    EXPECT_EQ( st.S, 1.0 );
    EXPECT_EQ( st.dS_dp, 0.0 );
    EXPECT_EQ( st.k_rel, 1.0 );
}

//---------------------------------------------------------------------------//
TEST( Retention, liakopoulos_corrected_law_hand_values )
{
    const auto r = liakopoulosParams( 0.0, 0.0 );
    const Retention ret;
    // S = 1 - 1.9722e-11 p_c^2.4279, k_rel = 1 - 2.207 (1 - S)^1.0121.
    const double s_ref[3] = { 0.99962098975067654, 0.9811339827154242,
                              0.89848015302315644 };
    const double k_ref[3] = { 0.99923957749031077, 0.96031573949118767,
                              0.78206220419925197 };
    const double d_ref[3] = { 9.2019898433243716e-7, 9.1609606730443164e-6,
                              2.4648003647507847e-5 };
    const double p_c[3] = { 1.0e3, 5.0e3, 10.0e3 };
    for ( int i = 0; i < 3; ++i )
    {
        const RetentionState st = ret( r, -p_c[i] );
        EXPECT_NEAR( st.S, s_ref[i], 1e-13 );
        EXPECT_NEAR( st.k_rel, k_ref[i], 1e-13 );
        EXPECT_NEAR( st.dS_dp, d_ref[i], 1e-12 * d_ref[i] );
        EXPECT_NEAR( ret.relativePermeability( r, st.S ), k_ref[i], 1e-12 );
    }
    // The printed factor 1.9722e+11 would give S(1 kPa) = -3.8e18, not ~1.
    const double s_typo = 1.0 - 1.9722e11 * std::pow( 1.0e3, 2.4279 );
    EXPECT_LT( s_typo, 0.0 );
    EXPECT_GT( ret( r, -1.0e3 ).S, 0.999 );
    EXPECT_LT( ret( r, -1.0e3 ).S, 1.0 );
}

TEST( Retention, liakopoulos_clamp_and_floor )
{
    const Retention ret;
    // k_rel = 0 at S = 0.5426 (s = 18.6 kPa): floored at k_rel_min.
    const auto r0 = liakopoulosParams( 0.0, 0.0 );
    EXPECT_NEAR( ret( r0, -20.0e3 ).S, 0.45371197456562345, 1e-13 );
    EXPECT_EQ( ret( r0, -20.0e3 ).k_rel, 0.0 );
    EXPECT_GT( ret( r0, -18.0e3 ).k_rel, 0.0 );
    // With s_res = 0, S stops at 0 (s = 25.7 kPa) with dS/dp_w = 0.
    EXPECT_EQ( ret( r0, -30.0e3 ).S, 0.0 );
    EXPECT_EQ( ret( r0, -30.0e3 ).dS_dp, 0.0 );
    EXPECT_GT( ret( r0, -25.0e3 ).S, 0.0 );
    // OGS-like S_min = 0.2 (reached at 23.4 kPa) and porousLab's 1e-4 floor.
    const auto r = liakopoulosParams( 0.2, 1.0e-4 );
    EXPECT_EQ( ret( r, -24.0e3 ).S, 0.2 );
    EXPECT_EQ( ret( r, -24.0e3 ).dS_dp, 0.0 );
    EXPECT_EQ( ret( r, -24.0e3 ).k_rel, 1.0e-4 );
    EXPECT_GT( ret( r, -23.0e3 ).S, 0.2 );
    EXPECT_GT( ret( r, -23.0e3 ).dS_dp, 0.0 );
    EXPECT_EQ( ret( r, -20.0e3 ).k_rel, 1.0e-4 );
    EXPECT_NEAR( ret( r, -5.0e3 ).k_rel, 0.96031573949118767, 1e-13 );
    EXPECT_EQ( ret.relativePermeability( r, 0.2 ), 1.0e-4 );
}

//---------------------------------------------------------------------------//
TEST( Retention, gardner_hand_values )
{
    const auto r = gardnerParams();
    const Retention ret;
    // psi = -1 m: S_e = exp(-0.5); psi = -2 m: S_e = exp(-1).
    const double e1 = std::exp( -0.5 );
    RetentionState st = ret( r, -9810.0 );
    EXPECT_NEAR( st.S, 0.1 + 0.8 * e1, 1e-15 );
    EXPECT_NEAR( st.dS_dp, 0.8 * 0.5 / 9810.0 * e1, 1e-15 * st.dS_dp );
    EXPECT_NEAR( st.k_rel, e1, 1e-15 );
    st = ret( r, -19620.0 );
    EXPECT_NEAR( st.S, 0.1 + 0.8 * std::exp( -1.0 ), 1e-15 );
    EXPECT_NEAR( st.k_rel, std::exp( -1.0 ), 1e-15 );
    EXPECT_NEAR( ret.relativePermeability( r, 0.1 + 0.8 * e1 ), e1, 1e-14 );
}

TEST( Retention, linear_hand_values )
{
    const auto r = linearParams();
    RetentionState st = Retention{}( r, -2500.0 );
    EXPECT_NEAR( st.S, 0.8, 1e-15 );
    EXPECT_NEAR( st.dS_dp, 0.8e-4, 1e-19 );
    EXPECT_EQ( st.k_rel, 1.0 );
    st = Retention{}( r, -2.0e4 );
    EXPECT_EQ( st.S, 0.2 );
    EXPECT_EQ( st.dS_dp, 0.0 );
    EXPECT_EQ( st.k_rel, 1.0 );
    EXPECT_EQ( Retention{}.relativePermeability( r, 0.5 ), 1.0 );
}

//---------------------------------------------------------------------------//
TEST( Retention, derivative_matches_central_difference )
{
    const Retention ret;
    struct Case
    {
        RetentionParams r;
        std::vector<double> p;
    };
    const std::vector<Case> cases = {
        { slopeVanGenuchten(),
          { -100.0, -500.0, -1.0e3, -2.0e3, -5.0e3, -1.0e4, -5.0e4, -2.0e5 } },
        { liakopoulosParams( 0.2, 1e-4 ),
          { -100.0, -1.0e3, -5.0e3, -1.0e4, -2.0e4, -2.3e4 } },
        { gardnerParams(), { -10.0, -1.0e3, -9810.0, -5.0e4 } },
        { linearParams(), { -10.0, -2500.0, -9000.0 } } };
    for ( const auto& c : cases )
    {
        for ( const double p : c.p )
        {
            const double h = 1.0e-4 * std::abs( p );
            const double fd = ( ret.saturation( c.r, p + h ) -
                                ret.saturation( c.r, p - h ) ) /
                              ( 2.0 * h );
            const double d = ret( c.r, p ).dS_dp;
            SCOPED_TRACE( std::to_string( int( c.r.model ) ) + " p_w " +
                          std::to_string( p ) );
            EXPECT_GT( d, 0.0 );
            EXPECT_NEAR( d, fd, 1e-6 * d );
        }
    }
}

TEST( Retention, monotone_and_bounded_for_every_law )
{
    const Retention ret;
    auto vg_floor = slopeVanGenuchten();
    vg_floor.k_rel_min = 1.0e-8;
    RetentionParams sat;
    for ( const auto& r :
          { slopeVanGenuchten(), vg_floor, liakopoulosParams( 0.0, 0.0 ),
            liakopoulosParams( 0.2, 1e-4 ), gardnerParams(), linearParams(),
            sat } )
    {
        const double s_max =
            r.model == RetentionModel::Liakopoulos ? 1.0 : r.s_sat;
        double S_prev = 2.0, k_prev = 2.0;
        for ( const double p : pressureSweep() ) // decreasing p_w
        {
            SCOPED_TRACE( std::to_string( int( r.model ) ) + " p_w " +
                          std::to_string( p ) );
            const RetentionState st = ret( r, p );
            EXPECT_EQ( ret.saturation( r, p ), st.S );
            EXPECT_LE( st.S, S_prev );
            EXPECT_LE( st.k_rel, k_prev );
            EXPECT_GE( st.dS_dp, 0.0 );
            EXPECT_GE( st.S, r.s_res );
            EXPECT_LE( st.S, s_max );
            EXPECT_GE( st.k_rel, r.k_rel_min );
            EXPECT_LE( st.k_rel, 1.0 );
            S_prev = st.S;
            k_prev = st.k_rel;
        }
    }
}

} // namespace
