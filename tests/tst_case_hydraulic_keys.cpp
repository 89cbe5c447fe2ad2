// The hydraulic keys in a case file: a tabulated initial pore-pressure
// profile, a held pore pressure on every point, rain on a polyline (its
// length derived), a hyetograph, and the warnings of the reader and of the
// point check.
#include <io/mpm_case_reader.hpp>
#include <mpm_test_case_reader.hpp>
#include <mpm_test_toml.hpp>
#include <setup/mpm_conditions.hpp>
#include <setup/mpm_point_check.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
//! A saturated case: `body` in its [[bodies]] table, `boundary` and
//! `stage` appended after the gravity stage's keys.
std::string hydraulicCase( const std::string& body, const std::string& stage )
{
    using namespace mpm_test;
    return caseToml( "hydraulic", "saturated" ) +
           gridToml( "0.5", "[20, 10]" ) +
           twoPhaseSoilToml( "2700.0", "4.5e-9", "1.0e7", "0.33" ) +
           soilBodyToml( rectangleToml( "10.0", "3.0" ) ) + body + "\n" +
           fixedBelowToml( "[[-1.0, 0.2], [10.0, 0.2]]" ) +
           stageToml( "gravity", "quasi_static", "1.0" ) + stage;
}

const char* const profile_body =
    "initial_pore_pressure_profile = [[0.0, 19620.0], [2.0, 0.0], "
    "[3.0, -29430.0]]\n";

const std::string hydraulic_stage =
    "\n[[stages.pore_pressures]]\nwhere = \"all\"\nhold = \"initial\"\n" +
    mpm_test::polylineInflowToml( "[[0.0, 3.0], [4.0, 3.0], [8.0, 6.0]]",
                                  "1.0e-5" ) +
    "[[stages.inflows]]\nwhere = \"polyline\"\nmeasured_on = \"horizontal\"\n"
    "polyline_m = [[0.0, 3.0], [4.0, 3.0], [8.0, 6.0], [12.0, 6.0]]\n"
    "flux_m_per_s = 2.0e-5\nponding = false\n";

//---------------------------------------------------------------------------//
TEST( HydraulicKeys, profile_hold_and_polyline_inflow_are_read )
{
    const mpm::CaseConfig c = mpm::parseCase(
        hydraulicCase( profile_body, hydraulic_stage ), "h.toml" );
    const std::vector<std::array<double, 2>> profile = {
        { 0.0, 19620.0 }, { 2.0, 0.0 }, { 3.0, -29430.0 } };
    EXPECT_EQ( c.bodies[0].initial_pore_pressure_profile, profile );
    ASSERT_EQ( c.stages[0].pore_pressures.size(), 1u );
    const mpm::PorePressureCondition& held = c.stages[0].pore_pressures[0];
    EXPECT_TRUE( held.hold_initial );
    EXPECT_EQ( held.points.kind, mpm::PointSelection::Kind::All );
    EXPECT_TRUE( held.time_function.empty() );

    ASSERT_EQ( c.stages[0].inflows.size(), 2u );
    const mpm::WaterInflow& along = c.stages[0].inflows[0];
    EXPECT_EQ( along.points.kind, mpm::PointSelection::Kind::Polyline );
    EXPECT_FALSE( along.onGridEdge() );
    EXPECT_EQ( along.points.polyline_measure, mpm::LineMeasure::AlongLine );
    EXPECT_EQ( along.points.polyline_m.size(), 3u );
    EXPECT_DOUBLE_EQ( along.length_m, 4.0 + 5.0 ); // 4 m, then a 3-4-5
    EXPECT_TRUE( along.ponding );
    const mpm::WaterInflow& level = c.stages[0].inflows[1];
    EXPECT_EQ( level.points.polyline_measure, mpm::LineMeasure::Horizontal );
    EXPECT_DOUBLE_EQ( level.length_m, 12.0 );
    EXPECT_FALSE( level.ponding );
}

// A hyetograph: blocks of rain in mm/h, zero before the first block, the
// last to the stage's end; the mean over any span is the blocks' depth over
// it. Exclusive with flux_m_per_s and time_function; no negative rain.
TEST( HydraulicKeys, a_hyetograph_is_rain_in_blocks_of_time )
{
    const std::string rain =
        "\n[[stages.inflows]]\nwhere = \"surface_cells\"\nlength_m = 10.0\n"
        "hyetograph_mm_per_h = [[600.0, 10.0], [3600.0, 30.0], [7200.0, "
        "0.0]]\n";
    const mpm::CaseConfig c =
        mpm::parseCase( hydraulicCase( "", rain ), "h.toml" );
    ASSERT_EQ( c.stages[0].inflows.size(), 1u );
    const mpm::WaterInflow& inflow = c.stages[0].inflows[0];
    EXPECT_DOUBLE_EQ( inflow.flux_m_per_s, 1.0e-3 / 3600.0 );
    const mpm::TimeFunction& f = inflow.time_function;
    EXPECT_DOUBLE_EQ( mpm::evaluateTimeFunction( f, 300.0 ), 0.0 );
    EXPECT_DOUBLE_EQ( mpm::evaluateTimeFunction( f, 601.0 ), 10.0 );
    EXPECT_DOUBLE_EQ( mpm::evaluateTimeFunction( f, 3599.0 ), 10.0 );
    EXPECT_DOUBLE_EQ( mpm::evaluateTimeFunction( f, 3601.0 ), 30.0 );
    EXPECT_DOUBLE_EQ( mpm::evaluateTimeFunction( f, 1.0e5 ), 0.0 );
    // 3000 s at 10 mm/h in the first hour; 600 s at 10, 400 s at 30.
    EXPECT_NEAR( mpm::meanOfTimeFunction( f, 0.0, 3600.0 ),
                 10.0 * 3000.0 / 3600.0, 1.0e-12 );
    EXPECT_NEAR( mpm::meanOfTimeFunction( f, 3000.0, 4000.0 ), 18.0, 1.0e-12 );
    EXPECT_NEAR( mpm::meanOfTimeFunction( f, 0.0, 1.0e4 ),
                 ( 10.0 * 3000.0 + 30.0 * 3600.0 ) / 1.0e4, 1.0e-12 );

    using mpm_test::case_reader::errorsOf;
    const auto with = [&]( const std::string& extra )
    { return errorsOf( hydraulicCase( "", rain + extra ) ); };
    EXPECT_NE( with( "flux_m_per_s = 1.0e-5\n" )
                   .find( "'stages[0].inflows[0].flux_m_per_s': not allowed "
                          "with hyetograph_mm_per_h" ),
               std::string::npos )
        << with( "flux_m_per_s = 1.0e-5\n" );
    EXPECT_NE( with( "time_function = [[0.0, 1.0]]\n" )
                   .find( "'stages[0].inflows[0].time_function': not allowed "
                          "with hyetograph_mm_per_h" ),
               std::string::npos );
    std::string negative = rain;
    negative.replace( negative.find( "30.0" ), 4, "-3.0" );
    const std::string negative_error =
        errorsOf( hydraulicCase( "", negative ) );
    EXPECT_NE( negative_error.find(
                   "'stages[0].inflows[0].hyetograph_mm_per_h[1][1]'" ),
               std::string::npos )
        << negative_error;
    EXPECT_NE( negative_error.find( "mm/h" ), std::string::npos );
    const std::string evaporation = errorsOf( hydraulicCase(
        "", "\n[[stages.inflows]]\nwhere = \"surface_cells\"\nlength_m = "
            "10.0\nflux_m_per_s = 1.0e-5\ntime_function = [[0.0, 1.0], "
            "[10.0, -0.5]]\n" ) );
    EXPECT_NE( evaporation.find( "evaporation is not modelled" ),
               std::string::npos )
        << evaporation;
}

// Polyline points outside the grid are warnings at the point, with the
// file, line and column, in file order; the case is read.
TEST( HydraulicKeys, polyline_points_outside_the_grid_are_warnings )
{
    const mpm::CaseConfig c = mpm::parseCase(
        hydraulicCase( profile_body, hydraulic_stage ), "h.toml" );
    ASSERT_EQ( c.warnings.size(), 3u );
    const std::string grid =
        "the grid spans x in [0, 10] m and y in [0, 5] m); ";
    EXPECT_EQ( c.warnings[0],
               "h.toml:24:15: warning: key 'boundaries[0].polyline_m[0]': the "
               "point (-1, 0.2) m lies outside the grid (1 of the 2 points "
               "do; " +
                   grid +
                   "it selects only the grid's nodes below it, the line "
                   "extended horizontally beyond its ends" );
    const std::string inflow_tail =
        "its pieces outside the grid feed no cell: their flux goes to the "
        "cells the line crosses inside it";
    EXPECT_EQ( c.warnings[1],
               "h.toml:35:39: warning: key 'stages[0].inflows[0].polyline_m[2]"
               "': the point (8, 6) m lies outside the grid (1 of the 3 points "
               "do; " +
                   grid + inflow_tail );
    EXPECT_EQ( c.warnings[2],
               "h.toml:40:39: warning: key 'stages[0].inflows[1].polyline_m[2]"
               "': the point (8, 6) m lies outside the grid (2 of the 4 points "
               "do; " +
                   grid + inflow_tail );
}

// The case's identity (the checkpoint's fingerprint) covers the new keys.
TEST( HydraulicKeys, fingerprint_covers_the_new_keys )
{
    const std::string base = hydraulicCase( profile_body, hydraulic_stage );
    const std::string fingerprint =
        mpm::parseCase( base, "h.toml" ).fingerprint;
    const auto changed = [&]( const std::string& from, const std::string& to )
    {
        std::string text = base;
        text.replace( text.find( from ), from.size(), to );
        return mpm::parseCase( text, "h.toml" ).fingerprint;
    };
    EXPECT_NE( changed( "[3.0, -29430.0]", "[3.0, -29000.0]" ), fingerprint );
    EXPECT_NE( changed( "measured_on = \"horizontal\"",
                        "measured_on = \"along_line\"" ),
               fingerprint );
    EXPECT_NE( changed( "[8.0, 6.0]]", "[8.0, 5.0]]" ), fingerprint );
}

// The point check warns of selections that pick none of the initial
// points (here a box above the soil in the second stage), not of those
// that pick some.
TEST( HydraulicKeys, point_check_warns_of_empty_selections )
{
    const std::string stages =
        hydraulic_stage + "\n" +
        mpm_test::stageToml( "rain", "dynamic", "1.0" ) +
        mpm_test::heldBoxToml( "[[0.0, 4.0], [10.0, 5.0]]", "0.0" ) +
        mpm_test::polylineInflowToml( "[[0.0, 4.5], [10.0, 4.5]]", "1.0e-5" );
    const mpm::CaseConfig c =
        mpm::parseCase( hydraulicCase( profile_body, stages ), "h.toml" );
    const mpm::PointFindings findings = mpm::checkPoints( c );
    EXPECT_TRUE( findings.refusals.empty() );
    const std::string tail = "': selects no material point at the points' "
                             "initial positions (the run checks again at the "
                             "stage start)";
    EXPECT_EQ( findings.warnings,
               std::vector<std::string>(
                   { "key 'stages[1].pore_pressures[0].where" + tail,
                     "key 'stages[1].inflows[0].where" + tail } ) );
}

} // namespace
