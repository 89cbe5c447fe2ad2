// End-to-end tests of the rainslide CLI: exit codes, messages, output files.
#include <mpm_test_cli.hpp>
#include <mpm_test_hdf5.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace
{
namespace fs = std::filesystem;

using mpm_test::runCommand;
using mpm_test::writeCase;

//! The test block (mpm_test::blockCaseText) with one dynamic stage of 0.2 s;
//! `stage_extra` is appended to the stage.
std::string blockCase( const std::string& solver_extra,
                       const std::string& stage_extra )
{
    return mpm_test::blockCaseText(
        solver_extra, "\n" + mpm_test::stageToml( "load", "dynamic", "0.2" ) +
                          "snapshot_interval_s = 0.05\n" + stage_extra );
}

//! `text` without its fixed bottom boundary.
std::string withoutBottomBoundary( const std::string& text )
{
    return std::regex_replace(
        text,
        std::regex( "\\[\\[boundaries\\]\\]\nwhere = "
                    "\"bottom\"\ncondition = \"fixed\"\n" ),
        "" );
}

//---------------------------------------------------------------------------//
TEST( Cli, run_writes_hdf5_xdmf_and_metrics )
{
    const fs::path dir = mpm_test::freshTempDir( "run" );
    const fs::path file = writeCase( dir, blockCase( "", "" ) );
    const auto result = runCommand( mpm_test::runArgs( file, dir / "out" ) );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    EXPECT_NE( result.output.find( "MP-updates/s" ), std::string::npos );
    EXPECT_EQ( mpm_test::snapshotCount( dir / "out" / "particles.h5" ), 4 );
    EXPECT_TRUE( fs::exists( dir / "out" / "particles.xdmf" ) );
    EXPECT_FALSE( fs::exists( dir / "out" / "particles.h5.partial" ) );
    std::ifstream in( dir / "out" / "metrics.json" );
    const auto metrics = nlohmann::json::parse( in );
    for ( const char* key : { "steps", "wall_s", "mp_updates_per_s", "backend",
                              "threads", "n_particles", "n_cells", "dt_s" } )
        EXPECT_TRUE( metrics.contains( key ) ) << key;
    EXPECT_EQ( metrics["n_particles"], 4 * 4 * 8 );
    EXPECT_EQ( metrics["status"], "completed" );
}

// --set overrides keys of the case (here the stage's duration: 2 of the
// 4 snapshots) and is recorded in metrics.json; a bad one is bad input.
TEST( Cli, set_overrides_keys_and_is_recorded )
{
    const fs::path dir = mpm_test::freshTempDir( "set" );
    const fs::path file = writeCase( dir, blockCase( "", "" ) );
    const auto result = runCommand( mpm_test::runArgs(
        file, dir / "out",
        " --set stages[0].duration_s=0.1 --set solver.courant_number=0.4" ) );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    EXPECT_EQ( mpm_test::snapshotCount( dir / "out" / "particles.h5" ), 2 );
    std::ifstream in( dir / "out" / "metrics.json" );
    const auto metrics = nlohmann::json::parse( in );
    EXPECT_EQ( metrics["overrides"],
               nlohmann::json( { "stages[0].duration_s=0.1",
                                 "solver.courant_number=0.4" } ) );
    const auto bad = runCommand( "check " + file.string() +
                                 " --set solver.courant_number=7" );
    mpm_test::expectExit( bad, 2, "--set solver.courant_number=7:1:" );
}

TEST( Cli, bad_case_is_rejected_and_nothing_is_written )
{
    const fs::path dir = mpm_test::freshTempDir( "bad" );
    std::string text = blockCase( "", "" );
    text = std::regex_replace( text, std::regex( "poisson_ratio = 0.3" ),
                               "poisson_ratio = 0.7" );
    const fs::path file = writeCase( dir, text );
    const auto result = runCommand( "run " + file.string() + " --out " +
                                    ( dir / "out" ).string() );
    EXPECT_EQ( result.exit_code, 2 );
    EXPECT_NE( result.output.find( file.string() + ":13:" ), std::string::npos )
        << result.output;
    EXPECT_NE( result.output.find( "poisson_ratio" ), std::string::npos );
    EXPECT_NE( result.output.find( "found 0.7" ), std::string::npos );
    EXPECT_FALSE( fs::exists( dir / "out" ) );
    // `check` reports the same error.
    EXPECT_EQ( runCommand( "check " + file.string() ).exit_code, 2 );
}

TEST( Cli, check_accepts_the_shipped_cases )
{
    for ( const auto& entry : fs::directory_iterator( RAINSLIDE_CASES_DIR ) )
    {
        if ( entry.path().extension() != ".toml" )
            continue;
        const auto result = runCommand( "check " + entry.path().string() );
        EXPECT_EQ( result.exit_code, 0 ) << result.output;
    }
}

TEST( Cli, time_step_above_the_limit_is_refused_with_numbers )
{
    const fs::path dir = mpm_test::freshTempDir( "dt" );
    const fs::path file = writeCase( dir, blockCase( "dt_s = 0.01", "" ) );
    const auto result = runCommand( mpm_test::runArgs( file, dir / "out" ) );
    mpm_test::expectExit( result, 2, "dt_s = 0.01 s exceeds the stable limit" );
    EXPECT_FALSE( fs::exists( dir / "out" ) );
}

// A strength reduction on a held skeleton would never fail: refused.
TEST( Cli, fos_refuses_the_seepage_and_quasi_static_schemes )
{
    for ( const std::string scheme : { "seepage", "quasi_static" } )
    {
        const fs::path dir = mpm_test::freshTempDir( "fos_" + scheme );
        const auto result =
            runCommand( "fos " + std::string( RAINSLIDE_CASES_DIR ) +
                        "/terzaghi.toml --out " + ( dir / "out" ).string() +
                        " --set 'solver.scheme=\"" + scheme + "\"'" );
        mpm_test::expectExit( result, 2,
                              "key 'solver.scheme': rainslide fos needs a "
                              "dynamic scheme (\"explicit\" or "
                              "\"semi_implicit\"), found \"" +
                                  scheme + "\"" );
        EXPECT_FALSE( fs::exists( dir / "out" ) );
    }
}

TEST( Cli, unstable_run_stops_with_a_diagnosis_and_readable_output )
{
    const fs::path dir = mpm_test::freshTempDir( "unstable" );
    // Any speed above 1e-6 x the wave speed counts as unstable here.
    const fs::path file =
        writeCase( dir, blockCase( "instability_speed_factor = 1.0e-6", "" ) );
    const auto result = runCommand( mpm_test::runArgs( file, dir / "out" ) );
    EXPECT_EQ( result.exit_code, 1 );
    for ( const char* fragment : { "material point", "is unstable: speed",
                                   "position (", "at step", "CFL limit" } )
        EXPECT_NE( result.output.find( fragment ), std::string::npos )
            << fragment << "\n"
            << result.output;
    // The snapshot at the failure was written and the file is readable.
    EXPECT_EQ( mpm_test::snapshotCount( dir / "out" / "particles.h5" ), 1 );
    std::ifstream in( dir / "out" / "metrics.json" );
    EXPECT_EQ( nlohmann::json::parse( in )["status"], "unstable" );
}

TEST( Cli, point_leaving_the_grid_is_an_error_or_removed )
{
    const fs::path dir = mpm_test::freshTempDir( "leave" );
    // Sideways gravity pushes the block out through the open right side.
    const std::string stage = "gravity_m_per_s2 = [400.0, 0.0]\n";
    const fs::path file =
        writeCase( dir, withoutBottomBoundary( blockCase( "", "" ) ) + stage );
    const auto result = runCommand( mpm_test::runArgs( file, dir / "out" ) );
    mpm_test::expectExit( result, 1, "left the grid" );

    const fs::path file_remove = writeCase(
        dir, blockCase( "remove_points_leaving_grid = true", "" ) + stage );
    writeCase( dir, withoutBottomBoundary(
                        blockCase( "remove_points_leaving_grid = true", "" ) ) +
                        stage );
    const auto removed =
        runCommand( mpm_test::runArgs( file_remove, dir / "out2" ) );
    EXPECT_EQ( removed.exit_code, 0 ) << removed.output;
    std::ifstream in( dir / "out2" / "metrics.json" );
    EXPECT_GT( nlohmann::json::parse( in )["removed_points"].get<int>(), 0 );
}

//---------------------------------------------------------------------------//
// The total-stress slope (the paper's Fig. 10) runs to completion.
TEST( Cli, total_stress_slope_runs_to_completion )
{
    const fs::path dir = mpm_test::freshTempDir( "slope_total_stress" );
    const auto result = runCommand( "run " RAINSLIDE_CASES_DIR
                                    "/slope_total_stress.toml --quiet --out " +
                                    ( dir / "out" ).string() );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    std::ifstream in( dir / "out" / "metrics.json" );
    const auto metrics = nlohmann::json::parse( in );
    EXPECT_EQ( metrics["status"], "completed" );
    // It is a collapse: material moves by metres.
    EXPECT_GT( metrics["deformation"]["max_displacement_m"].get<double>(),
               1.0 );
}

//---------------------------------------------------------------------------//
// A two-phase run reports the largest p_w and 99th percentile over its
// snapshots: a saturated column 2 m high, hydrostatic from its top, holds
// rho_w g 1.75 m in its bottom cell (one p_w per cell, that of the cell's
// centre, 0.25 m up); its grains are as dense as water, so the skeleton
// has no buoyant weight to put on the water.
TEST( Cli, two_phase_run_reports_pore_pressure_extremes )
{
    const fs::path dir = mpm_test::freshTempDir( "pore_pressure" );
    using namespace mpm_test;
    const fs::path file = writeCase(
        dir, "\n" + caseToml( "hydrostatic_column", "saturated" ) +
                 gridToml( "0.5", "[1, 5]" ) +
                 twoPhaseSoilToml( "1000.0", "1.0e-10", "1.0e7", "0.3" ) +
                 soilBodyToml( column_polygon ) +
                 "initial_pore_pressure_pa = 19620.0\n"
                 "initial_pore_pressure_gradient_pa_per_m = -9810.0\n" +
                 boundaryToml( "bottom", "fixed" ) + rollersToml() +
                 stageToml( "settle", "quasi_static", "0.5" ) +
                 "snapshot_interval_s = 0.1\n" );
    const auto result = runCommand( mpm_test::runArgs( file, dir / "out" ) );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    std::ifstream in( dir / "out" / "metrics.json" );
    const auto metrics = nlohmann::json::parse( in );
    ASSERT_TRUE( metrics.contains( "pore_pressure_max_pa" ) );
    const double p_max = metrics["pore_pressure_max_pa"];
    const double p99 = metrics["pore_pressure_p99_pa"];
    // The lowest points, 1.875 m deep (the cell's pressure slope gives each
    // point its own depth's pressure; one p_w per cell gave 1.75 m).
    EXPECT_NEAR( p_max, 9810.0 * 1.875, 0.02 * p_max );
    EXPECT_LE( p99, p_max );
    EXPECT_GT( p99, 0.8 * p_max );
}

} // namespace
