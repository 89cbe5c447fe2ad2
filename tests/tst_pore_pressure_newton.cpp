// The pore-pressure Newton iteration of Eq. 8: the lock-step version of
// several points gives each point exactly the increment of the one-point
// iteration, and the retention law's S-only evaluation matches the full one.
#include <physics/mpm_retention.hpp>
#include <physics/mpm_two_phase.hpp>

#include <gtest/gtest.h>

#include <cmath>
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

//---------------------------------------------------------------------------//
TEST( PorePressureNewton, lock_step_matches_one_point_at_a_time )
{
    constexpr int lanes = 4;
    const RetentionOf laws[2] = { { vanGenuchten() }, { liakopoulos() } };
    int checked = 0;
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
            for ( int l = 0; l < lanes; ++l, ++checked )
                EXPECT_NEAR( newton[l].dp, expected[l],
                             1.0e-12 * std::abs( expected[l] ) )
                    << "point " << start + l;
        }
    EXPECT_EQ( checked, 80 );
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
