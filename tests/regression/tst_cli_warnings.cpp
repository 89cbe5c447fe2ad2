// Warnings of the CLI: point selections that pick no point and polyline
// points outside the grid, at `check` and at `run`, on stderr, without
// changing the exit code.
#include <mpm_test_cli.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

using mpm_test::runCommand;

//! How often `text` occurs in `output`.
int occurrences( const std::string& output, const std::string& text )
{
    int count = 0;
    for ( auto at = output.find( text ); at != std::string::npos;
          at = output.find( text, at + 1 ) )
        ++count;
    return count;
}

//! "file:line:column:" of the first occurrence of `fragment` in `text`.
std::string positionOf( const fs::path& file, const std::string& text,
                        const std::string& fragment )
{
    const auto at = text.find( fragment );
    int line = 1;
    std::size_t line_start = 0;
    for ( std::size_t k = 0; k < at; ++k )
        if ( text[k] == '\n' )
        {
            ++line;
            line_start = k + 1;
        }
    return file.string() + ":" + std::to_string( line ) + ":" +
           std::to_string( at - line_start + 1 ) + ":";
}

/*!
  A saturated column 0.5 m x 2 m (cells of 0.5 m, grid up to 2.5 m), two
  short dynamic stages: the first holds p_w in a box above the soil
  (selects nothing), the second rains on a polyline above the soil
  (nothing) and on one along the soil's top that starts left of the grid.
*/
const std::string two_phase_text = mpm_test::saturatedColumnCaseText(
    "warned_column",
    "\n" + mpm_test::stageToml( "settle", "dynamic", "0.005" ) +
        mpm_test::heldBoxToml( "[[0.0, 2.2], [0.5, 2.4]]", "0.0" ) +
        mpm_test::stageToml( "rain", "dynamic", "0.005" ) +
        mpm_test::polylineInflowToml( "[[0.0, 2.3], [0.5, 2.3]]", "1.0e-4" ) +
        mpm_test::polylineInflowToml( "[[-0.5, 2.0], [0.5, 2.0]]", "1.0e-4" ) );

//! Expects `result` to have exited with 0 and to hold each of `warnings`
//! once.
void expectEachOnce( const mpm_test::CommandResult& result,
                     const std::vector<std::string>& warnings )
{
    EXPECT_EQ( result.exit_code, 0 ) << result.output;
    for ( const std::string& warning : warnings )
        EXPECT_EQ( occurrences( result.output, warning ), 1 ) << result.output;
}

//---------------------------------------------------------------------------//
TEST( CliWarnings, empty_selections_and_outside_points_warn_at_check_and_run )
{
    const fs::path dir = mpm_test::freshTempDir( "warnings" );
    const fs::path file = mpm_test::writeCase( dir, two_phase_text );
    const std::string prefix = file.string() + ": warning: ";
    const std::string outside =
        positionOf( file, two_phase_text, "[-0.5, 2.0]" ) +
        " warning: key 'stages[1].inflows[1].polyline_m[0]': the point "
        "(-0.5, 2) m lies outside the grid (1 of the 2 points do";
    const std::string pore_pressures =
        "key 'stages[0].pore_pressures[0].where': selects no material point";
    const std::string inflow =
        "key 'stages[1].inflows[0].where': selects no material point";

    const auto check = runCommand( "check " + file.string() );
    const std::string at_start = " at the points' initial positions";
    expectEachOnce( check, { outside, prefix + pore_pressures + at_start,
                             prefix + inflow + at_start } );
    EXPECT_EQ( occurrences( check.output, "warning:" ), 3 ) << check.output;

    const auto run =
        runCommand( mpm_test::runArgs( file, dir / "out", " --quiet" ) );
    const std::string at_stage = " at the stage start";
    expectEachOnce( run, { outside, prefix + pore_pressures + at_stage,
                           prefix + inflow + at_stage } );
    EXPECT_EQ( occurrences( run.output, "warning:" ), 3 ) << run.output;
    EXPECT_TRUE( fs::exists( dir / "out" / "metrics.json" ) );
}

// A dry case: a load box beside the block, a below_polyline line that
// reaches past the grid's right edge.
TEST( CliWarnings, dry_load_and_boundary_line_warn )
{
    const fs::path dir = mpm_test::freshTempDir( "warnings_dry" );
    const std::string text = mpm_test::blockCaseText(
        "",
        "\n" +
            mpm_test::fixedBelowToml( "[[0.0, 0.1], [2.0, 0.1], [2.5, 0.1]]" ) +
            mpm_test::stageToml( "load", "dynamic", "0.01" ) +
            "[[stages.loads]]\nwhere = \"box\"\n"
            "box_m = [[1.6, 0.0], [1.9, 2.0]]\n"
            "traction_pa = [0.0, -1.0e3]\nlength_m = 0.5\n" );
    const fs::path file = mpm_test::writeCase( dir, text );
    const std::string boundary =
        positionOf( file, text, "[2.5, 0.1]" ) +
        " warning: key 'boundaries[1].polyline_m[2]': the point (2.5, 0.1) "
        "m lies outside the grid";
    const std::string load =
        file.string() +
        ": warning: key 'stages[0].loads[0].where': selects no material point";
    for ( const std::string command : { "check", "run" } )
    {
        SCOPED_TRACE( command );
        const auto result = runCommand(
            command + " " + file.string() +
            ( command == "run"
                  ? " --out " + ( dir / "out" ).string() + " --quiet"
                  : "" ) );
        expectEachOnce( result, { boundary, load } );
    }
}

// A case whose selections all pick points warns of nothing.
TEST( CliWarnings, a_clean_case_has_no_warning )
{
    const fs::path dir = mpm_test::freshTempDir( "warnings_none" );
    const std::string load_all =
        "[[stages.loads]]\nwhere = \"all\"\n"
        "traction_pa = [0.0, -1.0e3]\nlength_m = 1.0\n";
    const fs::path file = mpm_test::writeCase(
        dir, mpm_test::blockCaseText(
                 "", "\n" + mpm_test::stageToml( "load", "dynamic", "0.01" ) +
                         load_all ) );
    const auto check = runCommand( "check " + file.string() );
    EXPECT_EQ( check.exit_code, 0 ) << check.output;
    EXPECT_EQ( check.output.find( "warning:" ), std::string::npos )
        << check.output;
    const auto run = runCommand( "run " + file.string() + " --out " +
                                 ( dir / "out" ).string() + " --quiet" );
    EXPECT_EQ( run.exit_code, 0 ) << run.output;
    EXPECT_EQ( run.output.find( "warning:" ), std::string::npos ) << run.output;
}

} // namespace
