// The water balance's terms on the host (physics::addPointStepWater,
// physics::WaterBalance) against values computed by hand.
#include <physics/mpm_point_water.hpp>

#include <gtest/gtest.h>

namespace
{
namespace physics = mpm::physics;

constexpr double V = 0.25, dt = 1.0e-3, n = 0.3, K_w = 2.2e9;

TEST( WaterBalanceTerms, free_point_takes_its_source_and_seepage )
{
    physics::WaterStepVolumes v;
    // source 0.2 /s, div q = 0.05 /s; not capped, not prescribed.
    physics::addPointStepWater( v, V, dt, 0.2, 0.05, 0.0, n / K_w, false, 0.0,
                                false, n, 0.5, 0.6, -1000.0, -900.0 );
    EXPECT_DOUBLE_EQ( v.point_inflow, 0.25 * 1.0e-3 * 0.2 );
    EXPECT_DOUBLE_EQ( v.flow_in, -0.25 * 1.0e-3 * 0.05 );
    EXPECT_EQ( v.runoff, 0.0 );
    EXPECT_EQ( v.prescribed, 0.0 );
}

TEST( WaterBalanceTerms, ponding_cap_runs_off_the_compression_above_zero )
{
    physics::WaterStepVolumes v;
    const double storage = n * 0.9 / K_w;
    physics::addPointStepWater( v, V, dt, 0.2, 0.0, 0.0, storage, true, 5.0e4,
                                false, n, 0.9, 1.0, -10.0, 0.0 );
    EXPECT_DOUBLE_EQ( v.runoff, 0.25 * storage * 5.0e4 );
    EXPECT_EQ( v.prescribed, 0.0 );
}

TEST( WaterBalanceTerms, prescribed_pressure_adds_what_eq8_did_not_give )
{
    physics::WaterStepVolumes v;
    const double storage = n * 0.5 / K_w;
    const double volume_change = 2.0e-4; // dt (source - r)
    // Held at 0 Pa from -2000 Pa, S 0.5 -> 0.8; a cap does not count then.
    physics::addPointStepWater( v, V, dt, 0.0, 0.1, volume_change, storage,
                                true, 10.0, true, n, 0.5, 0.8, -2000.0, 0.0 );
    EXPECT_DOUBLE_EQ(
        v.prescribed,
        0.25 * ( 0.3 * ( 0.8 - 0.5 ) + storage * 2000.0 - volume_change ) );
    EXPECT_EQ( v.runoff, 0.0 );
}

TEST( WaterBalanceTerms, stored_water_counts_the_compression )
{
    EXPECT_DOUBLE_EQ( physics::pointWaterVolume( V, n, 0.5, 1.1e6, K_w ),
                      0.25 * 0.3 * 0.5 * 1.0005 );
}

TEST( WaterBalanceTerms, ledger_closes_and_appends_stages )
{
    physics::WaterBalance first;
    first.begin( 10.0, 0.0 );
    first.addStep( { 1.0, 0.25, 0.5, -0.125 } );
    first.end( 11.125, 0.0 ); // 10 + 1 - 0.25 + 0.5 - 0.125
    EXPECT_DOUBLE_EQ( first.closureError(), 0.0 );
    physics::WaterBalance second;
    second.begin( 11.125, 0.0 );
    second.addStep( { 0.0, 0.0, 0.0, 1.0 } );
    second.end( 12.0, 0.25 ); // 0.125 m3/m unexplained
    first.append( second );
    EXPECT_DOUBLE_EQ( first.storedChange(), 2.25 );
    EXPECT_DOUBLE_EQ( first.closureError(), 0.125 );
    // The largest term is the stored change.
    EXPECT_DOUBLE_EQ( first.relativeClosureError(), 0.125 / 2.25 );
}

} // namespace
