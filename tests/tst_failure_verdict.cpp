// The failure verdict (solver/output/mpm_failure_verdict.hpp) on a block of
// points moved by hand: the reference state of each stage, the first
// failure, a detached later slide, an area jump after a quiet spell, the
// run-out and the line of a run that does not fail.
#include <solver/output/mpm_failure_verdict.hpp>

#include <mpm_device_type.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
// A 20 x 10 block of points 0.5 m apart (0.25 m^2 each), at rest.
mpm::HostSnapshot restingBlock()
{
    mpm::HostSnapshot s;
    for ( int j = 0; j < 10; ++j )
        for ( int i = 0; i < 20; ++i )
        {
            s.x.insert( s.x.end(), { 0.25 + 0.5 * i, 0.25 + 0.5 * j } );
            s.displacement.insert( s.displacement.end(), { 0.0, 0.0 } );
            s.eps_p_bar.push_back( 0.0 );
            s.vol.push_back( 0.25 );
            s.status.push_back( mpm::point_active );
            s.id.push_back( s.num_points++ );
        }
    return s;
}

// Moves the points with i0 <= i < i1 and j0 <= j < j1 by (dx, dy).
void movePatch( mpm::HostSnapshot& s, int i0, int i1, int j0, int j1, double dx,
                double dy )
{
    for ( int j = j0; j < j1; ++j )
        for ( int i = i0; i < i1; ++i )
        {
            const int p = 20 * j + i;
            s.x[2 * p] += dx;
            s.x[2 * p + 1] += dy;
            s.displacement[2 * p] += dx;
            s.displacement[2 * p + 1] += dy;
        }
}

mpm::RunProgress at( int stage, double stage_start_s, double time_s )
{
    mpm::RunProgress progress;
    progress.stage = stage == 0 ? "gravity" : "rain";
    progress.stage_index = stage;
    progress.time_s = time_s;
    progress.stage_time_s = time_s - stage_start_s;
    return progress;
}
} // namespace

//---------------------------------------------------------------------------//
TEST( LinkedGroups, links_chains_closer_than_the_distance )
{
    // 0-1-2 a chain 0.5 m apart, 3 alone 2 m further.
    const std::vector<double> xy = { 0.0, 0.0, 0.5, 0.0, 1.0, 0.0, 3.0, 0.0 };
    const std::vector<int> label = mpm::linkedGroups( xy, 0.75 );
    EXPECT_EQ( label, ( std::vector<int>{ 0, 0, 0, 1 } ) );
    EXPECT_EQ( mpm::linkedGroups( xy, 0.5 ),
               ( std::vector<int>{ 0, 1, 2, 3 } ) ); // strictly closer
}

//---------------------------------------------------------------------------//
TEST( FailureVerdict, finds_the_first_failure_and_the_later_slides )
{
    mpm::FailureVerdict verdict( { false, true } );
    // Quasi-static stage: the whole block settles 1 m; not analysed, and
    // its end state is the rain stage's reference.
    mpm::HostSnapshot s = restingBlock();
    movePatch( s, 0, 20, 0, 10, 0.0, -1.0 );
    verdict.add( at( 0, 0.0, 10.0 ), s );
    verdict.endStage( at( 0, 0.0, 10.0 ), s );
    EXPECT_EQ( verdict.snapshotsAnalysed(), 0 );

    // t = 0.5: points move 0.2 m without plastic strain: not sliding.
    movePatch( s, 0, 4, 0, 2, 0.2, 0.0 );
    verdict.add( at( 1, 10.0, 10.5 ), s );
    EXPECT_FALSE( verdict.failed() );
    EXPECT_NEAR( verdict.maxDisplacementM(), 0.2, 1e-12 );

    // t = 1: patch A (8 points, 2 m^2) has moved 0.6 m: the first failure.
    movePatch( s, 0, 4, 0, 2, 0.4, 0.0 );
    verdict.add( at( 1, 10.0, 11.0 ), s );
    ASSERT_TRUE( verdict.failed() );
    ASSERT_EQ( verdict.onsets().size(), 1u );
    EXPECT_EQ( verdict.onsets()[0].reason, "first failure" );
    EXPECT_DOUBLE_EQ( verdict.onsets()[0].stage_time_s, 1.0 );
    EXPECT_DOUBLE_EQ( verdict.onsets()[0].new_area_m2, 2.0 );
    EXPECT_DOUBLE_EQ( verdict.onsets()[0].x_min_m, 0.25 );
    EXPECT_DOUBLE_EQ( verdict.onsets()[0].x_max_m, 1.75 );
    EXPECT_NEAR( verdict.onsets()[0].y_m, 0.5 - 1.0, 1e-12 );
    EXPECT_EQ( verdict.runOutM(), 0.0 ); // within the block's outline

    // t = 2: patch B far away moves 0.3 m with plastic strain: detached.
    for ( int j = 8; j < 10; ++j )
        for ( int i = 16; i < 20; ++i )
            s.eps_p_bar[20 * j + i] = 0.1;
    movePatch( s, 16, 20, 8, 10, 0.3, 0.0 );
    verdict.add( at( 1, 10.0, 12.0 ), s );
    ASSERT_EQ( verdict.onsets().size(), 2u );
    EXPECT_EQ( verdict.onsets()[1].reason, "detached group" );
    EXPECT_DOUBLE_EQ( verdict.onsets()[1].x_min_m, 8.25 );
    EXPECT_DOUBLE_EQ( verdict.slidingAreaM2(), 4.0 );
    EXPECT_NEAR( verdict.runOutM(), 0.3, 1e-12 );

    // t = 3.5: quiet. t = 4: patch C beside A (4 m^2 in 0.5 s): area jump.
    verdict.add( at( 1, 10.0, 13.5 ), s );
    EXPECT_EQ( verdict.onsets().size(), 2u );
    movePatch( s, 4, 12, 0, 2, 0.6, 0.0 );
    verdict.add( at( 1, 10.0, 14.0 ), s );
    ASSERT_EQ( verdict.onsets().size(), 3u );
    EXPECT_EQ( verdict.onsets()[2].reason, "area jump" );
    EXPECT_DOUBLE_EQ( verdict.onsets()[2].new_area_m2, 4.0 );
    EXPECT_DOUBLE_EQ( verdict.slidingAreaM2(), 8.0 );
    // B reaches 0.3 m beyond the block's right side (x = 9.75 m).
    EXPECT_NEAR( verdict.runOutM(), 10.05 - 9.75, 1e-12 );
    EXPECT_NEAR( verdict.maxDisplacementM(), 0.6, 1e-12 );

    const nlohmann::json json = verdict.json( "cases/x.toml" );
    EXPECT_TRUE( json["failed"].get<bool>() );
    EXPECT_EQ( json["onsets"].size(), 3u );
    EXPECT_DOUBLE_EQ( json["first_failure"]["stage_time_s"].get<double>(),
                      1.0 );
    EXPECT_EQ( verdict.line( "cases/x.toml" )
                   .rfind( "FAILED: first slide "
                           "at t = 1 s",
                           0 ),
               0u );
}

//---------------------------------------------------------------------------//
TEST( FailureVerdict, a_run_without_a_slide_points_to_the_factor_of_safety )
{
    mpm::FailureVerdict verdict( { true } );
    mpm::HostSnapshot s = restingBlock();
    // A single point moving 2 m is not a sliding mass (0.25 m^2 < 1 m^2).
    movePatch( s, 5, 6, 5, 6, 2.0, 0.0 );
    verdict.add( at( 0, 0.0, 1.0 ), s );
    EXPECT_FALSE( verdict.failed() );
    EXPECT_NEAR( verdict.maxDisplacementM(), 2.0, 1e-12 );
    const std::string line = verdict.line( "cases/x.toml" );
    EXPECT_EQ( line.rfind( "no failure:", 0 ), 0u ) << line;
    EXPECT_NE( line.find( "rainslide fos cases/x.toml" ), std::string::npos );
    EXPECT_EQ( verdict.json( "cases/x.toml" )["factor_of_safety"],
               "rainslide fos cases/x.toml" );
}
