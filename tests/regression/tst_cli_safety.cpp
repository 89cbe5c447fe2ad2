// The CLI against hostile input and careless use (issue 12): a case that
// cannot finish or exceeds the budget is refused by `check` and `run`
// (exit 2, before any work), and a run never writes outside its folder.
#include <mpm_test_cli.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace
{
namespace fs = std::filesystem;

using mpm_test::runCommand;
using mpm_test::writeCase;

fs::path freshDir( const std::string& name )
{
    return mpm_test::freshTempDir( "safety_" + name );
}

//! The test block with one dynamic stage; `stage_extra` is appended to it.
std::string blockCase( const std::string& solver_extra,
                       const std::string& stage_extra,
                       const std::string& duration = "0.2" )
{
    return mpm_test::blockCaseText(
        solver_extra, "\n" +
                          mpm_test::stageToml( "load", "dynamic", duration ) +
                          stage_extra );
}

std::string readText( const fs::path& path )
{
    std::ifstream in( path );
    std::string text;
    std::getline( in, text );
    return text;
}

//! `check` and `run` both refuse the case with exit 2 and `fragment`.
void expectRefused( const std::string& name, const std::string& text,
                    const std::string& fragment )
{
    SCOPED_TRACE( name );
    const fs::path dir = freshDir( name );
    const fs::path file = writeCase( dir, text );
    const auto check = runCommand( "check " + file.string() );
    mpm_test::expectExit( check, 2, file.string() + ": error: " );
    mpm_test::expectExit( check, 2, fragment );
    const auto run =
        runCommand( mpm_test::runArgs( file, dir / "out", " --quiet" ) );
    EXPECT_EQ( run.exit_code, 2 ) << run.output;
    EXPECT_FALSE( fs::exists( dir / "out" ) );
}

//---------------------------------------------------------------------------//
TEST( CliSafety, check_refuses_a_device_as_case_file )
{
    mpm_test::expectExit( runCommand( "check /dev/zero" ), 2,
                          "/dev/zero: error: cannot open the case file: "
                          "expected a readable regular file" );
}

TEST( CliSafety, zero_or_tiny_time_step_cannot_finish )
{
    expectRefused( "courant", blockCase( "courant_number = 5e-324", "" ),
                   "stages[0] 'load' cannot finish" );
    std::string light = blockCase( "", "" );
    light.replace( light.find( "density_kg_per_m3 = 2000.0" ), 26,
                   "density_kg_per_m3 = 5e-324" );
    expectRefused( "density", light, "cannot finish" );
    expectRefused( "dt", blockCase( "dt_s = 1e-300", "" ),
                   "found dt = 1e-300 s (solver.dt_s = 1e-300 s)" );
}

TEST( CliSafety, long_run_and_snapshot_flood_exceed_the_budget )
{
    // duration 1e12 s: snapshots every step once (relative end tolerance).
    expectRefused( "duration",
                   blockCase( "", "snapshot_interval_s = 0.25", "1e12" ),
                   "cannot finish" );
    expectRefused( "snapshot_flood",
                   blockCase( "", "snapshot_interval_s = 1e-13", "5.0" ),
                   "cannot finish: expected at most 1e+12 steps, found 5e+13 "
                   "snapshots" );
    expectRefused( "snapshots", blockCase( "", "snapshot_interval_s = 1e-12" ),
                   "the run exceeds the budget: snapshots 2e+11 > 20000" );
    // The budget names its override, and the override works.
    const fs::path dir = freshDir( "override" );
    const fs::path file =
        writeCase( dir, blockCase( "", "snapshot_interval_s = 1e-5" ) );
    const auto refused = runCommand( "check " + file.string() );
    mpm_test::expectExit( refused, 2, "--max-snapshots N" );
    const auto accepted = runCommand( "check " + file.string() +
                                      " --max-snapshots 0 --max-output-gb 0" );
    mpm_test::expectExit( accepted, 0, "estimate: 128 points, 96 cells" );
}

TEST( CliSafety, point_errors_surface_at_check )
{
    // Once exit 1 at `run` only: a probe outside the soil, no point at all.
    expectRefused( "probe",
                   blockCase( "", "" ) +
                       "\n[probes]\ninterval_s = 0.05\npoints = [ { name = "
                       "\"air\", position_m = [1.0, 2.8] } ]\n",
                   "key 'probes.points[0].position_m': expected a point in "
                   "the soil" );
    std::string thin = blockCase( "", "" );
    const std::string polygon =
        "[[0.5, 0.0], [1.5, 0.0], [1.5, 2.0], [0.5, 2.0]]";
    thin.replace( thin.find( polygon ), polygon.size(),
                  "[[0.5, 0.0], [0.55, 0.0], [0.55, 0.05], [0.5, 0.05]]" );
    expectRefused( "thin", thin,
                   "bodies: expected material points inside the body "
                   "polygons, found none" );
}

TEST( CliSafety, unsafe_output_folders_are_refused )
{
    const fs::path dir = freshDir( "out_root" );
    const fs::path file = writeCase( dir, blockCase( "", "" ) );
    fs::create_directory_symlink( "/", dir / "link_to_root" );
    std::ofstream( dir / "a_file" ) << "x";
    for ( const std::string& out :
          { std::string( "/" ), std::string( "/etc" ),
            std::string( "/dev/shm" ), ( dir / "link_to_root" ).string(),
            ( dir / "a_file" ).string() } )
    {
        SCOPED_TRACE( out );
        mpm_test::expectExit(
            runCommand( mpm_test::runArgs( file, out, " --quiet" ) ), 2,
            "rainslide: error: --out '" + out +
                "': expected a folder of its own" );
    }
}

TEST( CliSafety, planted_symlinks_are_not_followed )
{
    const fs::path dir = freshDir( "symlinks" );
    const fs::path file =
        writeCase( dir, blockCase( "checkpoint_interval_s = 0.05", "" ) );
    const fs::path out = dir / "out";
    fs::create_directories( out );
    for ( const std::string name :
          { "particles.h5.partial", "checkpoint.h5.partial" } )
    {
        std::ofstream( dir / ( name + ".target" ) ) << "precious";
        fs::create_symlink( dir / ( name + ".target" ), out / name );
    }
    const auto result =
        runCommand( mpm_test::runArgs( file, out, " --quiet" ) );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    for ( const std::string name :
          { "particles.h5.partial", "checkpoint.h5.partial" } )
        EXPECT_EQ( readText( dir / ( name + ".target" ) ), "precious" ) << name;
    EXPECT_TRUE( fs::is_regular_file( out / "particles.h5" ) );
    EXPECT_TRUE( fs::is_regular_file( out / "checkpoint.h5" ) );
}

TEST( CliSafety, old_metrics_do_not_survive_a_failed_run )
{
    // A reused folder where the particle file cannot be written (a folder
    // sits at its temporary name): the run fails after it was accepted.
    const fs::path dir = freshDir( "stale_metrics" );
    const fs::path file = writeCase( dir, blockCase( "", "" ) );
    fs::create_directories( dir / "out" / "particles.h5.partial" );
    std::ofstream( dir / "out" / "metrics.json" )
        << "{\"status\": \"completed\"}\n";
    const auto result =
        runCommand( mpm_test::runArgs( file, dir / "out", " --quiet" ) );
    EXPECT_EQ( result.exit_code, 1 ) << result.output;
    EXPECT_FALSE( fs::exists( dir / "out" / "metrics.json" ) );
}

TEST( CliSafety, unconverged_quasi_static_stage_is_not_completed )
{
    // 0.02 s: far too short for the block to settle under gravity.
    const fs::path dir = freshDir( "unconverged" );
    const fs::path file = writeCase(
        dir, mpm_test::blockCaseText(
                 "", "\n" + mpm_test::stageToml( "settle", "quasi_static",
                                                 "0.02" ) ) );
    const auto result =
        runCommand( mpm_test::runArgs( file, dir / "out", " --quiet" ) );
    mpm_test::expectExit( result, 0, "did not converge" );
    std::ifstream in( dir / "out" / "metrics.json" );
    const auto metrics = nlohmann::json::parse( in );
    EXPECT_EQ( metrics["status"], "unconverged" );
    EXPECT_EQ( metrics["unconverged_stages"][0], "settle" );
}

} // namespace
