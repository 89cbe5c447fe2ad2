// The slope study's cases in short, coarse versions: the shipped base case
// on cells of 1 m runs through its equilibrium stage into the rainfall, and
// a rainfall that follows the surface adds the water that falls on the
// surface's horizontal projection.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#ifndef RAINSLIDE_CASES_DIR
#define RAINSLIDE_CASES_DIR "/work/main/cases"
#endif

namespace
{
MPM_TEST_BACKEND_SUITE( SlopeSmoke );

using mpm_test::waterVolume;

/*!
  cases/slope_base.toml on 1 m cells, 1 s of its gravity and suction stage
  (not to equilibrium: a smoke test) and 1 s of rainfall: the slope stays
  put, the points held at p_w = 0 are saturated, and water has entered the
  soil.
*/
TYPED_TEST( SlopeSmoke, coarse_base_case_wets_its_surface )
{
    auto config = mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_base.toml" );
    config.grid.cell_size_m = 1.0;
    config.grid.cells = { 72, 21 };
    config.stages[0].duration_s = 1.0;
    config.stages[1].duration_s = 1.0;
    config.stages[1].snapshot_interval_s = 0.0;
    config.stages[1].snapshot_times_s.clear();

    mpm::Simulation<TypeParam> sim( config );
    const double before = waterVolume( mpm::hostSnapshot( sim ) );
    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    ASSERT_EQ( summary.stages.size(), 2u );

    const auto snap = mpm::hostSnapshot( sim );
    double max_displacement = 0.0;
    int saturated = 0;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        ASSERT_TRUE( std::isfinite( snap.p_w[p] ) );
        max_displacement = std::max(
            max_displacement, std::hypot( snap.displacement[2 * p],
                                          snap.displacement[2 * p + 1] ) );
        if ( snap.p_w[p] > -1.0e3 )
            ++saturated;
    }
    EXPECT_LT( max_displacement, 0.05 );
    // The surface cells hold about a fifth of the points on 1 m cells.
    EXPECT_GT( saturated, snap.num_points / 8 );
    // Water entered: at least the surface cells' pore space filled up from
    // S = 0.23 (n (1 - S) = 0.23 per m^3, over ~75 m^2 of surface cells).
    EXPECT_GT( waterVolume( snap ) - before, 10.0 )
        << "water gained " << waterVolume( snap ) - before << " m^3/m";
}

/*!
  Rain that follows the surface on an L-shaped block (a 2 m wide step up
  from a 4 m wide base, zero gravity, sealed): the rain falls on the
  surface's horizontal projection, 4 m, so the soil gains q * 4 m * t,
  whatever the inclination or the height of the surface cells.
*/
TYPED_TEST( SlopeSmoke, rain_on_the_moving_surface_falls_on_its_projection )
{
    auto config = mpm_test::paperSoilColumn( 2.0, 1.0, 0.0 );
    config.grid.cells = { 16, 8 };
    config.bodies[0].polygon_m = { { 0.0, 0.0 }, { 4.0, 0.0 }, { 4.0, 1.0 },
                                   { 2.0, 1.0 }, { 2.0, 2.0 }, { 0.0, 2.0 } };
    config.bodies[0].initial_pore_pressure_pa = -2.0e4;
    mpm::WaterInflow inflow = mpm_test::surfaceCellsInflow( 1.0e-4 );
    inflow.ponding = false;
    inflow.follow_surface_interval_s = 0.1;
    config.stages[0].inflows = { inflow };

    mpm::Simulation<TypeParam> sim( config );
    const double before = waterVolume( mpm::hostSnapshot( sim ) );
    EXPECT_DOUBLE_EQ( sim.conditions.inflows[0].length_m, 4.0 );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const double added = waterVolume( mpm::hostSnapshot( sim ) ) - before;
    const double expected = 1.0e-4 * 4.0 * 1.0;
    EXPECT_NEAR( added, expected, 0.01 * expected );
    EXPECT_DOUBLE_EQ( sim.conditions.inflows[0].length_m, 4.0 );
}

/*!
  When the surface is detected again, only the inflows that follow it are
  selected again: an inflow on a fixed box keeps the points chosen at the
  stage start even after every point has moved down by one cell (selected
  again, the box would hold other points).
*/
TYPED_TEST( SlopeSmoke, fixed_inflows_keep_their_points_when_the_surface_moves )
{
    auto config = mpm_test::paperSoilColumn( 2.0, 1.0, -9.81 );
    mpm::WaterInflow fixed;
    fixed.points.kind = mpm::PointSelection::Kind::Box;
    fixed.points.box_m = { { { 0.0, 1.0 }, { 0.25, 1.25 } } };
    fixed.flux_m_per_s = 1.0e-5;
    mpm::WaterInflow following = mpm_test::surfaceCellsInflow( 1.0e-5 );
    following.follow_surface_interval_s = 0.1;
    config.stages[0].inflows = { fixed, following };

    mpm::Simulation<TypeParam> sim( config );
    auto inflowOf = [&]()
    {
        const auto h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), sim.water_particles.inflow_p );
        return std::vector<int>( h.data(), h.data() + h.span() );
    };
    const std::vector<int> before = inflowOf();
    ASSERT_EQ( std::count( before.begin(), before.end(), 0 ), 4 );
    ASSERT_EQ( std::count( before.begin(), before.end(), 1 ), 4 );
    // Every point one cell lower.
    auto x_h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                    sim.particles.x_p );
    for ( std::size_t p = 0; p < x_h.extent( 0 ); ++p )
        x_h( p, 1 ) -= 0.25;
    Kokkos::deep_copy( sim.particles.x_p, x_h );
    sim.conditions.update( 0.0, 0.1 );
    const std::vector<int> after = inflowOf();
    for ( std::size_t p = 0; p < before.size(); ++p )
        EXPECT_EQ( after[p] == 0, before[p] == 0 ) << "point " << p;
    EXPECT_EQ( std::count( after.begin(), after.end(), 1 ), 4 );
}

} // namespace
