#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>
#include <solver/output/mpm_metrics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
//---------------------------------------------------------------------------//
// The stop rule on a given history: nothing before a point has slid, then
// the window counts from the last step above the static speed.
TEST( StaticAgain, waits_for_a_slide_then_for_the_window )
{
    mpm::StaticStop stop;
    stop.static_speed_m_per_s = 0.01;
    stop.slide_displacement_m = 0.5;
    stop.window_s = 1.0;
    mpm::StageLoopState state;
    double displacement = 0.0;
    int displacement_calls = 0;
    auto maxDisplacement = [&]()
    {
        ++displacement_calls;
        return displacement;
    };
    auto step = [&]( const double speed, const double t )
    { return mpm::staticAgain( stop, speed, t, maxDisplacement, state ); };
    // At rest from the start, or a fast transient without a slide: no stop.
    EXPECT_FALSE( step( 0.0, 0.0 ) );
    EXPECT_FALSE( step( 0.3, 1.0 ) );
    EXPECT_FALSE( step( 0.0, 5.0 ) );
    displacement = 0.2; // creep
    EXPECT_FALSE( step( 0.005, 6.0 ) );
    EXPECT_FALSE( state.has_moved );
    // A slide, then it slows down.
    displacement = 2.0;
    EXPECT_FALSE( step( 1.5, 7.0 ) );
    EXPECT_TRUE( state.has_moved );
    const int calls_at_slide = displacement_calls;
    EXPECT_FALSE( step( 0.005, 8.0 ) );
    EXPECT_FALSE( step( 0.005, 8.9 ) );
    // A jolt restarts the window.
    EXPECT_FALSE( step( 0.02, 9.0 ) );
    EXPECT_FALSE( step( 0.005, 9.5 ) );
    EXPECT_FALSE( step( 0.005, 10.4 ) );
    EXPECT_TRUE( step( 0.005, 10.5 ) );
    // The displacement is not evaluated again after the slide.
    EXPECT_EQ( displacement_calls, calls_at_slide );
}

MPM_TEST_BACKEND_SUITE( StaticStop );

//! A dynamic stage of an elastic column (4 m, E = 1e8 Pa) under gravity.
mpm::CaseConfig dampedColumn( const double gravity, const double duration_s )
{
    mpm::StageConfig stage;
    stage.name = "drop";
    stage.type = mpm::StageType::Dynamic;
    stage.gravity_m_per_s2 = { 0.0, -gravity };
    stage.damping = 0.2;
    stage.duration_s = duration_s;
    // The dynamic overshoot (2 x the static settlement of 1.2 mm) counts
    // as the "slide".
    stage.static_stop.static_speed_m_per_s = 1.0e-4;
    stage.static_stop.slide_displacement_m = 1.5e-3;
    stage.static_stop.window_s = 0.1;
    return mpm_test::columnCase(
        4.0, 0.1, mpm_test::elasticMaterial( 1.0e8, 0.3, 2000.0 ), stage );
}

//---------------------------------------------------------------------------//
// Gravity switched on suddenly sets the column ringing (largest speed about
// g H / c = 0.15 m/s); the damped ringing dies out and the stage ends
// static, at the elastic settlement rho g H^2 / (2 E_c).
TYPED_TEST( StaticStop, damped_column_stops_once_static_at_its_settlement )
{
    const double duration_s = 20.0;
    auto config = dampedColumn( 9.81, duration_s );
    mpm::Simulation<TypeParam> sim( config );
    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    const auto& stage = summary.stages.at( 0 );
    EXPECT_EQ( stage.stop_reason, "static_again" );
    EXPECT_LT( stage.duration_s, 0.5 * duration_s );
    EXPECT_GT( stage.max_speed_m_per_s, 0.05 );
    EXPECT_LT( stage.max_speed_m_per_s, 0.5 );
    EXPECT_LT( sim.maxPointSpeed(), 1.0e-4 );

    const double E = 1.0e8, nu = 0.3, H = 4.0;
    const double E_c = E * ( 1 - nu ) / ( ( 1 + nu ) * ( 1 - 2 * nu ) );
    const double settlement = 2000.0 * 9.81 * H * H / ( 2.0 * E_c );
    const auto snap = mpm::hostSnapshot( sim );
    double top_settlement = 0.0;
    double top_y = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
        if ( snap.x[2 * p + 1] > top_y )
        {
            top_y = snap.x[2 * p + 1];
            top_settlement = -snap.displacement[2 * p + 1];
        }
    EXPECT_NEAR( top_settlement, settlement, 0.03 * settlement );
    // The reductions behind the stop: the largest displacement is the top's
    // settlement; the point-speed reduction agrees with the step's.
    EXPECT_NEAR( sim.maxDisplacement(), top_settlement,
                 1.0e-3 * top_settlement );
    const double speed_of_step = sim.maxPointSpeed();
    sim.stateChanged();
    EXPECT_NEAR( sim.maxPointSpeed(), speed_of_step, 1.0e-9 );
}

// Without a load nothing slides: the stage runs for its whole duration.
TYPED_TEST( StaticStop, stage_at_rest_runs_its_duration )
{
    auto config = dampedColumn( 0.0, 0.05 );
    mpm::Simulation<TypeParam> sim( config );
    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    EXPECT_EQ( summary.stages.at( 0 ).stop_reason, "duration" );
    EXPECT_NEAR( summary.stages.at( 0 ).duration_s, 0.05, 1.0e-12 );
}

//---------------------------------------------------------------------------//
// The count rule against a sorted nearest-rank percentile: "the p-th
// percentile of the speeds is below v" holds exactly when at most
// allowedPointsNotBelow(N, p) speeds are >= v.
TEST( StaticAgain, count_rule_is_the_nearest_rank_percentile )
{
    EXPECT_EQ( mpm::allowedPointsNotBelow( 804, 100.0 ), 0 );
    EXPECT_EQ( mpm::allowedPointsNotBelow( 804, 99.0 ), 8 );
    EXPECT_EQ( mpm::allowedPointsNotBelow( 100, 99.0 ), 1 );
    EXPECT_EQ( mpm::allowedPointsNotBelow( 1000, 99.9 ), 1 ); // 0.99999...
    EXPECT_EQ( mpm::allowedPointsNotBelow( 3, 50.0 ), 1 );
    EXPECT_EQ( mpm::allowedPointsNotBelow( 0, 50.0 ), 0 );
    std::mt19937 random( 3 );
    std::uniform_real_distribution<double> speed( 0.0, 1.0 );
    int checks = 0;
    for ( const int n : { 1, 2, 7, 100, 333 } )
    {
        std::vector<double> speeds( n );
        for ( double& v : speeds )
            v = speed( random );
        std::vector<double> sorted = speeds;
        std::sort( sorted.begin(), sorted.end() );
        for ( const double p : { 0.5, 10.0, 50.0, 90.0, 99.0, 99.7, 100.0 } )
        {
            const std::size_t rank = std::max<std::size_t>(
                1, static_cast<std::size_t>( std::ceil( p * n / 100.0 ) ) );
            for ( const double v : sorted )
                for ( const double threshold : { v, std::nextafter( v, 2.0 ) } )
                {
                    const long not_below = std::count_if(
                        speeds.begin(), speeds.end(),
                        [&]( double s ) { return !( s < threshold ); } );
                    EXPECT_EQ( not_below <= mpm::allowedPointsNotBelow( n, p ),
                               sorted[rank - 1] < threshold )
                        << "n " << n << " p " << p << " v " << threshold;
                    ++checks;
                }
        }
    }
    EXPECT_GT( checks, 5000 );
}

/*
  An elastic block (2 m x 1 m, 800 points) settling against the left edge
  on a roller floor, and 4 points (a block of one cell, 0.5 m away) pushed
  along the floor by a load all stage long. With speed_percentile = 99 (8
  of the 804 points may be as fast as the static speed) the stage ends
  once the block is static; with 100 the 4 moving points keep it going
  for its duration.
*/
mpm::CaseConfig blockAndSlider( const double percentile )
{
    mpm::StageConfig stage;
    stage.name = "settle";
    stage.type = mpm::StageType::Dynamic;
    stage.damping = 0.5;
    stage.duration_s = 3.0;
    stage.static_stop.static_speed_m_per_s = 1.0e-4;
    stage.static_stop.slide_displacement_m = 0.01; // the slider's
    stage.static_stop.window_s = 0.1;
    stage.static_stop.speed_percentile = percentile;
    mpm::PointLoad push;
    push.points.kind = mpm::PointSelection::Kind::Box;
    push.points.box_m = { mpm::Point2{ 2.45, -0.05 },
                          mpm::Point2{ 2.65, 0.15 } };
    push.traction_pa = { 2.0, 0.0 }; // 2 N on 20 kg
    push.length_m = 1.0;
    stage.loads = { push };
    auto c = mpm_test::columnCase(
        1.0, 0.1, mpm_test::elasticMaterial( 1.0e7, 0.3, 2000.0 ), stage );
    c.grid.cells = { 30, 12 };
    c.bodies[0].polygon_m = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 }, { 0.0, 1.0 } };
    mpm::BodyConfig slider = c.bodies[0];
    slider.polygon_m = {
        { 2.5, 0.0 }, { 2.6, 0.0 }, { 2.6, 0.1 }, { 2.5, 0.1 } };
    c.bodies.push_back( slider );
    // Left edge fix_x, roller floor (columnCase: left, right, bottom).
    c.boundaries = { c.boundaries[0], c.boundaries[2] };
    c.boundaries[1].condition = mpm::BoundaryCondition::FixY;
    c.stages[0].boundaries = c.boundaries;
    return c;
}

TYPED_TEST( StaticStop, percentile_ignores_a_few_moving_points )
{
    auto config = blockAndSlider( 99.0 );
    mpm::Simulation<TypeParam> sim( config );
    ASSERT_EQ( sim.numActivePoints(), 804 );
    mpm::RunObserver observer;
    const auto stage = mpm::runStages( sim, config, observer ).stages.at( 0 );
    EXPECT_EQ( stage.stop_reason, "static_again" );
    EXPECT_LT( stage.duration_s, 2.0 );
    // The statistic at the stage end: the slider's 4 points are the only
    // ones at or above the static speed, the 99th percentile below it.
    EXPECT_EQ( stage.speed_percentile, 99.0 );
    EXPECT_EQ( stage.allowed_points_not_below, 8 );
    EXPECT_EQ( stage.points_not_below_static_speed, 4 );
    EXPECT_LT( stage.speed_at_percentile_m_per_s, 1.0e-4 );
    EXPECT_GT( sim.maxPointSpeed(), 0.01 );
    EXPECT_EQ( sim.pointsNotBelowSpeed( 1.0e-4 ), 4 );
    std::printf( "  p99: static again at %.3f s, 99th percentile %.3g m/s, "
                 "largest speed %.3g m/s\n",
                 stage.duration_s, stage.speed_at_percentile_m_per_s,
                 sim.maxPointSpeed() );

    auto every_point = blockAndSlider( 100.0 );
    mpm::Simulation<TypeParam> sim_max( every_point );
    const auto full =
        mpm::runStages( sim_max, every_point, observer ).stages.at( 0 );
    EXPECT_EQ( full.stop_reason, "duration" );
    EXPECT_NEAR( full.duration_s, 3.0, 1.0e-9 );
    EXPECT_EQ( full.allowed_points_not_below, 0 );
    EXPECT_EQ( full.points_not_below_static_speed, 4 );
    EXPECT_NEAR( full.speed_at_percentile_m_per_s, sim_max.maxPointSpeed(),
                 1.0e-12 );

    // metrics.json: the statistic of a stage with a static stop only.
    const auto json = mpm::stageMetrics( stage, false );
    ASSERT_TRUE( json.contains( "static_stop" ) );
    EXPECT_EQ( json["static_stop"]["speed_percentile"], 99.0 );
    EXPECT_EQ( json["static_stop"]["points_not_below_static_speed"], 4 );
    EXPECT_EQ( json["static_stop"]["allowed_points_not_below"], 8 );
    EXPECT_EQ( json["static_stop"]["speed_at_percentile_m_per_s"],
               stage.speed_at_percentile_m_per_s );
    EXPECT_FALSE( mpm::stageMetrics( mpm::StageSummary(), false )
                      .contains( "static_stop" ) );
}

} // namespace
