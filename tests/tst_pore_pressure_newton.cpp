// The pore-pressure Newton iteration of Eq. 8: its increment against the
// closed form of a linear retention law and of a saturated point, and
// against an independent bisection of Eq. 8 for the nonlinear laws (a
// wetting step that saturates included); the lock-step version of several
// points gives each point the increment of the one-point iteration; the
// retention law's S-only evaluation matches the full one.
#include <physics/mpm_retention.hpp>
#include <physics/mpm_two_phase.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using namespace mpm::physics;

RetentionParams vanGenuchten()
{
    RetentionParams r;
    r.model = RetentionModel::VanGenuchten;
    r.alpha_per_pa = 4.4e-4;
    r.n_vg = 3.04;
    r.s_res = 0.23;
    r.k_rel_min = 1.0e-6;
    return r;
}

RetentionParams liakopoulos()
{
    RetentionParams r;
    r.model = RetentionModel::Liakopoulos;
    r.s_res = 0.2;
    r.k_rel_min = 1.0e-4;
    return r;
}

struct RetentionOf
{
    RetentionParams params;
    SaturationState operator()( const double p_w ) const
    {
        return Retention{}.saturationState( params, p_w );
    }
};

//---------------------------------------------------------------------------//
TEST( PorePressureNewton, saturation_state_matches_full_state )
{
    RetentionParams gardner;
    gardner.model = RetentionModel::Gardner;
    gardner.alpha_per_m = 0.5;
    gardner.s_res = 0.1;
    gardner.s_sat = 0.9;
    RetentionParams linear;
    linear.model = RetentionModel::Linear;
    linear.s_res = 0.2;
    linear.suction_range_pa = 1.0e4;
    const Retention retention;
    for ( const RetentionParams& r : { vanGenuchten(), liakopoulos(), gardner,
                                       linear, RetentionParams{} } )
        for ( const double p_w :
              { 1.0e3, 0.0, -1.0, -2.0e3, -2.0e4, -5.0e4, -3.0e5, -1.0e9 } )
        {
            const RetentionState full = retention( r, p_w );
            const SaturationState part = retention.saturationState( r, p_w );
            EXPECT_EQ( part.S, full.S ) << "p_w = " << p_w;
            EXPECT_EQ( part.dS_dp, full.dS_dp ) << "p_w = " << p_w;
        }
}

//! Eq. 8's left side less its right side at increment dp (long double).
long double residual( const RetentionParams& law, const double p_w,
                      const double n, const double K_w,
                      const double volume_change, const long double dp )
{
    const double S0 = Retention{}.saturation( law, p_w );
    const double S1 =
        Retention{}.saturation( law, static_cast<double>( p_w + dp ) );
    return static_cast<long double>( n ) * ( S1 - S0 ) +
           static_cast<long double>( n ) * S0 * dp / K_w - volume_change;
}

//! The root of Eq. 8 by bisection alone (the left side grows with dp),
//! bracketed by the storage term as the solver does, widened.
double bisectedIncrement( const RetentionParams& law, const double p_w,
                          const double n, const double K_w,
                          const double volume_change )
{
    const double S0 = Retention{}.saturation( law, p_w );
    const long double bound =
        2.0L * std::fabs( volume_change ) * K_w / ( n * S0 ) + 1.0L;
    long double lo = -bound, hi = bound;
    for ( int k = 0; k < 200; ++k )
    {
        const long double mid = 0.5L * ( lo + hi );
        ( residual( law, p_w, n, K_w, volume_change, mid ) > 0.0L ? hi : lo ) =
            mid;
    }
    return static_cast<double>( 0.5L * ( lo + hi ) );
}

//---------------------------------------------------------------------------//
// A linear law inside its range and a saturated point have the closed form
// dp = volume_change / (n dS/dp + n S / K_w).
TEST( PorePressureNewton, increment_is_the_closed_form_of_a_linear_law )
{
    RetentionParams linear;
    linear.model = RetentionModel::Linear;
    linear.s_res = 0.2;
    linear.suction_range_pa = 1.0e5;
    const double n = 0.3, K_w = 2.0e9;
    const RetentionOf law{ linear };
    const RetentionOf saturated{ RetentionParams{} };
    for ( const double volume_change : { -2.0e-3, -1.0e-6, 1.0e-6, 2.0e-3 } )
    {
        const double p_w = -5.0e4; // the result stays in (-1e5, 0)
        const double S = Retention{}.saturation( linear, p_w );
        const double slope = 0.8 / 1.0e5;
        const double exact = volume_change / ( n * slope + n * S / K_w );
        // S itself is rounded: the root is known to S's ulp over the slope.
        const double rounding =
            4.0 * std::numeric_limits<double>::epsilon() * S / slope;
        EXPECT_NEAR(
            porePressureIncrement( law, p_w, S, n, K_w, volume_change ), exact,
            rounding )
            << volume_change;
        const double exact_saturated = volume_change * K_w / n;
        EXPECT_NEAR( porePressureIncrement( saturated, 1.0e4, 1.0, n, K_w,
                                            volume_change ),
                     exact_saturated, 1.0e-12 * std::abs( exact_saturated ) )
            << volume_change;
    }
}

//---------------------------------------------------------------------------//
// The nonlinear laws against the bisected root: drying, wetting, and
// wetting steps that saturate the point (the root beyond p_w = 0, where the
// storage drops by orders of magnitude).
TEST( PorePressureNewton, increment_is_the_root_of_eq8 )
{
    const double n = 0.3, K_w = 2.0e9;
    int nonzero = 0;
    for ( const RetentionParams& params : { vanGenuchten(), liakopoulos() } )
        for ( const double p_w : { -3.0e5, -2.0e4, -2.0e3, -50.0 } )
            for ( const double volume_change :
                  { -1.0e-2, -1.0e-5, -1.0e-8, 1.0e-8, 1.0e-5, 1.0e-2 } )
            {
                const RetentionOf law{ params };
                const double S = Retention{}.saturation( params, p_w );
                const double dp =
                    porePressureIncrement( law, p_w, S, n, K_w, volume_change );
                const double root =
                    bisectedIncrement( params, p_w, n, K_w, volume_change );
                EXPECT_NEAR( dp, root,
                             1.0e-10 * ( std::abs( p_w ) + std::abs( root ) ) +
                                 3.0e-9 )
                    << "p_w " << p_w << ", volume change " << volume_change;
                // Wetting raises p_w, drying lowers it.
                EXPECT_EQ( dp > 0.0, volume_change > 0.0 );
                nonzero += dp != 0.0;
            }
    EXPECT_EQ( nonzero, 2 * 4 * 6 );
}

//---------------------------------------------------------------------------//
TEST( PorePressureNewton, lock_step_matches_one_point_at_a_time )
{
    constexpr int lanes = 4;
    const RetentionOf laws[2] = { { vanGenuchten() }, { liakopoulos() } };
    int nonzero = 0;
    for ( const RetentionOf& law : laws )
        for ( int start = 0; start < 40; start += lanes )
        {
            RetentionOf retention[lanes];
            PorePressureNewton newton[lanes];
            SaturationState stored[lanes];
            double expected[lanes];
            for ( int l = 0; l < lanes; ++l )
            {
                const int k = start + l;
                // Suctions, wetting, drying and no change at all.
                const double p_w = -1.0e3 * ( 1 + k % 23 ) - 37.0 * k;
                const double volume_change =
                    ( k % 5 == 0 ) ? 0.0
                                   : 1.0e-9 * std::pow( 10.0, k % 7 ) *
                                         ( k % 2 ? 1.0 : -1.0 );
                const RetentionState s0 = Retention{}( law.params, p_w );
                retention[l] = law;
                stored[l] = SaturationState{ s0.S, s0.dS_dp };
                newton[l] =
                    PorePressureNewton( p_w, s0.S, 0.3, 2.0e9, volume_change );
                // A lane with nothing to solve (a held point) stays put.
                newton[l].done = k % 11 == 3;
                expected[l] =
                    newton[l].done
                        ? 0.0
                        : porePressureIncrement( law, p_w, s0.S, 0.3, 2.0e9,
                                                 volume_change, &stored[l] );
            }
            porePressureIncrements( retention, newton, stored, true );
            // The same iterations; with FMA (-march=native) the compiler
            // may contract the lock-step and the scalar loops differently,
            // so they agree to rounding, not bit for bit.
            for ( int l = 0; l < lanes; ++l )
            {
                EXPECT_NEAR( newton[l].dp, expected[l],
                             1.0e-12 * std::abs( expected[l] ) )
                    << "point " << start + l;
                nonzero += expected[l] != 0.0;
            }
        }
    // Not a comparison of zeros: every lane that has water to move moves
    // it (k % 5 == 0 has none, k % 11 == 3 is held).
    EXPECT_EQ( nonzero, 2 * ( 40 - 8 - 4 + 1 ) );
}

//---------------------------------------------------------------------------//
TEST( PorePressureNewton, known_start_state_saves_an_evaluation_only )
{
    const RetentionOf law{ vanGenuchten() };
    for ( const double volume_change : { -1.0e-6, 1.0e-8, 3.0e-5 } )
    {
        const double p_w = -2.0e4;
        const RetentionState s0 = Retention{}( law.params, p_w );
        const SaturationState stored{ s0.S, s0.dS_dp };
        EXPECT_EQ( porePressureIncrement( law, p_w, s0.S, 0.3, 2.0e9,
                                          volume_change, &stored ),
                   porePressureIncrement( law, p_w, s0.S, 0.3, 2.0e9,
                                          volume_change ) );
    }
}

} // namespace
