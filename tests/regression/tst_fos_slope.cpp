// `rainslide fos` against published factors of safety: the infinite slope
// (closed form, dry and with slope-parallel seepage) and the homogeneous
// slope of Griffiths & Lane (1999) at two cell sizes; the failure
// criterion's thresholds halved and doubled; a history (--every-s). Serial only
// (whole searches: about 1.5 min together).
#include <mpm_test_cli.hpp>
#include <mpm_test_infinite_slope.hpp>
#include <mpm_test_temp_dir.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_fos_run.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
//! Runs the case's stages on Serial, then searches its factor of safety.
//! With `before`, the points' state the search starts from.
mpm::FosReport searchCase( const mpm::CaseConfig& config,
                           const mpm::FosOptions& options,
                           mpm::HostSnapshot* before = nullptr )
{
    mpm::Simulation<Kokkos::Serial> sim( config );
    mpm::RunObserver quiet;
    const mpm::RunSummary summary = mpm::runStages( sim, config, quiet );
    EXPECT_TRUE( summary.stages.back().converged );
    if ( before )
        *before = mpm::hostSnapshot( sim );
    return mpm::searchFos( sim, config, config.stages.size() - 1, options );
}

//! Search options starting at `start` with bracketing steps of `step`.
mpm::FosOptions startingAt( const double start, const double step )
{
    mpm::FosOptions options;
    options.search.start = start;
    options.search.step = step;
    return options;
}

//! The Griffiths-Lane case with cells of `cell_m` (1 or 0.5 m); with the
//! folder `solver_defaults`, the case without its [solver] table (every
//! solver key at its default, as for a user who sets none), written there.
mpm::CaseConfig
griffithsLane( const double cell_m,
               const mpm_test::TempDir* solver_defaults = nullptr )
{
    const int n = int( std::lround( 1.0 / cell_m ) );
    std::string path =
        std::string( RAINSLIDE_CASES_DIR ) + "/fos_griffiths_lane.toml";
    if ( solver_defaults )
    {
        std::ifstream in( path );
        std::string text( ( std::istreambuf_iterator<char>( in ) ),
                          std::istreambuf_iterator<char>() );
        const auto solver = text.find( "[solver]" );
        const auto stages = text.find( "[[stages]]" );
        EXPECT_LT( solver, stages );
        text.erase( solver, stages - solver );
        path = ( solver_defaults->path / "fos_griffiths_lane.toml" ).string();
        std::ofstream( path ) << text;
    }
    return mpm::readCaseFile( path,
                              { "grid.cell_size_m=" + std::to_string( cell_m ),
                                "grid.cells=[" + std::to_string( 60 * n ) +
                                    ", " + std::to_string( 23 * n ) + "]" } );
}

void print( const char* what, const mpm::FosReport& r, const double reference )
{
    double wall = 0.0;
    for ( const mpm::FosTrialRecord& t : r.trials )
        wall += t.wall_s;
    std::printf( "%s: FS %.4f [%.4f, %.4f] against %.4f (%+.2f %%), %zu "
                 "trials, %.1f s\n",
                 what, r.search.factor, r.search.stable, r.search.failing,
                 reference, 100.0 * ( r.search.factor / reference - 1.0 ),
                 r.trials.size(), wall );
}

/*!
  Runs `rainslide fos CASE ARGS --out OUT` on Serial, quietly, searching
  from `start` in steps of 0.05 to +- 0.02; expects exit 0 and returns the
  JSON document `OUT/json_name`.
*/
nlohmann::json runFosCli( const std::string& case_and_args,
                          const std::filesystem::path& out, const double start,
                          const char* json_name )
{
    const auto result = mpm_test::runCommand(
        "fos " + case_and_args + " --out " + out.string() +
        " --backend serial --quiet --step 0.05 --tolerance 0.02 --start " +
        std::to_string( start ) );
    EXPECT_EQ( result.exit_code, 0 ) << result.output;
    std::ifstream in( out / json_name );
    return nlohmann::json::parse( in );
}

// Bishop's simplified method for Griffiths & Lane's example 1 (their
// Table 1: 1.38; their finite elements: about 1.4).
const double griffiths_lane_bishop = 1.38;

} // namespace

//---------------------------------------------------------------------------//
// Dry: 2.396 closed form; found 2.419 (+0.95 %: the base row's points sit
// h/4 and 3h/4 above the base, so the cohesion term is that of a depth
// between d - h/2 and d).
TEST( FosInfiniteSlope, dry_matches_the_closed_form )
{
    const mpm::CaseConfig config = mpm::parseCase(
        mpm_test::infiniteSlopeCase( false, 0.5 ), "infinite_slope_dry" );
    const mpm::FosReport r = searchCase( config, startingAt( 2.35, 0.05 ) );
    const double exact = mpm_test::infiniteSlopeFactor( false );
    print( "infinite slope, dry", r, exact );
    ASSERT_TRUE( r.search.found ) << r.search.status;
    EXPECT_NEAR( r.search.factor / exact, 1.0, 0.03 );
}

// Slope-parallel seepage, water table at the surface: 1.339 closed form.
TEST( FosInfiniteSlope, parallel_seepage_matches_the_closed_form )
{
    const mpm::CaseConfig config = mpm::parseCase(
        mpm_test::infiniteSlopeCase( true, 0.5 ), "infinite_slope_seepage" );
    mpm::HostSnapshot before;
    const mpm::FosReport r =
        searchCase( config, startingAt( 1.33, 0.03 ), &before );
    const double exact = mpm_test::infiniteSlopeFactor( true );
    print( "infinite slope, seepage", r, exact );
    ASSERT_TRUE( r.search.found ) << r.search.status;
    EXPECT_NEAR( r.search.factor / exact, 1.0, 0.04 );
    // The water was frozen: at the end of the failing trial (the layer
    // slid) every point's p_w is the one it started with.
    ASSERT_TRUE( r.mechanism );
    const mpm::HostSnapshot& after = *r.mechanism;
    ASSERT_EQ( after.num_points, before.num_points );
    std::map<int, double> p_w_before;
    double p_max = 0.0;
    for ( int p = 0; p < before.num_points; ++p )
    {
        p_w_before[before.id[p]] = before.p_w[p];
        p_max = std::max( p_max, std::abs( before.p_w[p] ) );
    }
    double change = 0.0;
    for ( int p = 0; p < after.num_points; ++p )
        change = std::max( change,
                           std::abs( after.p_w[p] - p_w_before[after.id[p]] ) );
    EXPECT_GT( p_max, 30e3 );
    EXPECT_LT( change, 1e-9 * p_max );
    // The seepage halves the friction term: far below the dry slope.
    EXPECT_LT( r.search.failing, mpm_test::infiniteSlopeFactor( false ) - 0.5 );
}

//---------------------------------------------------------------------------//
// With no solver key set: the trials use B-bar by default (without it the
// volumetric locking at psi = 0 gives FS 1.656 on 1 m cells).
TEST( FosGriffithsLane, two_cell_sizes_agree_with_bishop )
{
    const mpm_test::TempDir tmp;
    std::vector<double> found;
    for ( const double cell_m : { 1.0, 0.5 } )
    {
        const mpm::CaseConfig config = griffithsLane( cell_m, &tmp );
        EXPECT_FALSE( config.solver.bbar_given );
        const mpm::FosReport r = searchCase( config, startingAt( 1.35, 0.05 ) );
        print( cell_m == 1.0 ? "Griffiths-Lane, 1 m cells"
                             : "Griffiths-Lane, 0.5 m cells",
               r, griffiths_lane_bishop );
        ASSERT_TRUE( r.search.found ) << r.search.status;
        EXPECT_NEAR( r.search.factor / griffiths_lane_bishop, 1.0, 0.03 );
        found.push_back( r.search.factor );
    }
    // Mesh sensitivity: 1.394 at 1 m, 1.369 at 0.5 m.
    EXPECT_LT( std::abs( found[0] - found[1] ), 0.075 );
}

// The criterion's thresholds (displacement and creep limits) halved and
// doubled: the factor moves by at most one bracket.
TEST( FosGriffithsLane, insensitive_to_the_criterion_thresholds )
{
    const mpm::CaseConfig config = griffithsLane( 1.0 );
    std::vector<double> found;
    for ( const double scale : { 1.0, 0.5, 2.0 } )
    {
        mpm::FosOptions options = startingAt( 1.35, 0.05 );
        options.criterion = options.criterion.scaled( scale );
        const mpm::FosReport r = searchCase( config, options );
        ASSERT_TRUE( r.search.found ) << r.search.status;
        std::printf( "thresholds x%.1f: FS %.4f\n", scale, r.search.factor );
        found.push_back( r.search.factor );
    }
    EXPECT_LE( std::abs( found[1] - found[0] ), 0.03 );
    EXPECT_LE( std::abs( found[2] - found[0] ), 0.03 );
}

//---------------------------------------------------------------------------//
TEST( FosCli, writes_fos_json_and_the_mechanism )
{
    const auto dir = mpm_test::freshTempDir( "fos_cli" );
    const auto out = dir / "out";
    const std::string case_file =
        std::string( RAINSLIDE_CASES_DIR ) + "/fos_griffiths_lane.toml";
    const nlohmann::json j = runFosCli( case_file, out, 1.35, "fos.json" );
    EXPECT_EQ( j.at( "status" ), "found" );
    const double fs = j.at( "factor_of_safety" ).get<double>();
    EXPECT_NEAR( fs, griffiths_lane_bishop, 0.05 );
    const double stable = j.at( "bracket" )[0], failing = j.at( "bracket" )[1];
    EXPECT_LT( stable, failing );
    EXPECT_LE( failing - stable, 0.04 + 1e-12 );
    EXPECT_GT( j.at( "wall_s" ).get<double>(), 0.0 );
    ASSERT_GE( j.at( "trials" ).size(), 2u );
    bool saw_stable = false, saw_failing = false;
    for ( const auto& t : j.at( "trials" ) )
    {
        const bool fails = t.at( "verdict" ) == "fails";
        ( fails ? saw_failing : saw_stable ) = true;
        EXPECT_EQ( fails, t.at( "factor" ).get<double>() >= failing );
        for ( const char* key :
              { "u_max_m", "u_three_quarters_m", "last_quarter_m", "ke_ratio",
                "reason", "history" } )
            EXPECT_TRUE( t.contains( key ) ) << key;
        // 20 samples (fewer if the trial stopped at the displacement
        // limit), the last at the trial's end.
        const auto& history = t.at( "history" );
        const std::size_t samples = history.at( "t_s" ).size();
        ASSERT_GE( samples, 1u );
        EXPECT_LE( samples, 20u );
        if ( t.at( "reason" ) != "displacement_limit" )
        {
            EXPECT_EQ( samples, 20u );
        }
        EXPECT_DOUBLE_EQ( history.at( "t_s" ).back().get<double>(),
                          t.at( "duration_s" ).get<double>() );
        EXPECT_DOUBLE_EQ( history.at( "u_max_m" ).back().get<double>(),
                          t.at( "u_max_m" ).get<double>() );
    }
    EXPECT_TRUE( saw_stable && saw_failing );
    EXPECT_TRUE( j.at( "criterion" ).contains( "text" ) );
    EXPECT_DOUBLE_EQ( j.at( "mechanism" ).at( "factor" ).get<double>(),
                      failing );
    EXPECT_EQ( j.at( "state" ).at( "from" ), "stages" );
    EXPECT_EQ( j.at( "state" ).at( "stage" ), "gravity" );
    // Only the search's files, inside --out.
    std::vector<std::string> names = mpm_test::listDir( out );
    std::sort( names.begin(), names.end() );
    EXPECT_EQ( names, ( std::vector<std::string>{ "fos.json", "mechanism.h5",
                                                  "mechanism.xdmf" } ) );
}

// The state of a checkpoint (here 1 s into the gravity stage, which
// converges at 1.5 s) instead of running the stages.
TEST( FosCli, searches_from_a_checkpoint )
{
    const auto dir = mpm_test::freshTempDir( "fos_cli_restart" );
    const std::string case_file =
        std::string( RAINSLIDE_CASES_DIR ) + "/fos_griffiths_lane.toml";
    auto result = mpm_test::runCommand( mpm_test::runArgs(
        case_file, dir / "run", " --quiet --checkpoint-every-s 1.0" ) );
    ASSERT_EQ( result.exit_code, 0 ) << result.output;
    const auto checkpoint = dir / "run" / "checkpoint.h5";
    const nlohmann::json j =
        runFosCli( case_file + " --restart " + checkpoint.string(), dir / "fos",
                   1.35, "fos.json" );
    EXPECT_EQ( j.at( "state" ).at( "from" ), checkpoint.string() );
    EXPECT_NEAR( j.at( "state" ).at( "time_s" ).get<double>(), 1.0, 0.01 );
    EXPECT_NEAR( j.at( "factor_of_safety" ).get<double>(), 1.39, 0.03 );
    // A checkpoint of another case is refused before any work.
    const auto other =
        mpm_test::writeCase( dir, mpm_test::infiniteSlopeCase( false, 0.5 ) );
    result = mpm_test::runCommand( "fos " + other.string() + " --restart " +
                                   checkpoint.string() + " --out " +
                                   ( dir / "other" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_FALSE( std::filesystem::exists( dir / "other" / "fos.json" ) );
}

// Ctrl-C in a trial stops the search at the trial's next step: exit 130,
// no fos.json. The trial is made long (2,000 periods: minutes) and the
// signal sent 3 s after the start, the checkpoint's state restored at
// once; a search that let the trial finish would be killed 30 s later.
TEST( FosCli, ctrl_c_in_a_trial_stops_the_search )
{
    const auto dir = mpm_test::freshTempDir( "fos_cli_interrupt" );
    const std::string case_file =
        std::string( RAINSLIDE_CASES_DIR ) + "/fos_griffiths_lane.toml";
    const auto ran = mpm_test::runCommand( mpm_test::runArgs(
        case_file, dir / "run", " --quiet --checkpoint-every-s 1.0" ) );
    ASSERT_EQ( ran.exit_code, 0 ) << ran.output;
    const auto start = std::chrono::steady_clock::now();
    const auto fos = mpm_test::runRainslide(
        "fos " + case_file + " --restart " +
            ( dir / "run" / "checkpoint.h5" ).string() + " --out " +
            ( dir / "fos" ).string() + " --backend serial --periods 2000",
        dir / "fos.log", "timeout --preserve-status -k 30 -s INT 3 " );
    const double wall_s = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start )
                              .count();
    EXPECT_EQ( fos.exit_code, 130 ) << fos.output;
    EXPECT_LT( wall_s, 15.0 ) << fos.output;
    EXPECT_NE( fos.output.find( "interrupted in the trial at F = " ),
               std::string::npos )
        << fos.output;
    EXPECT_FALSE( std::filesystem::exists( dir / "fos" / "fos.json" ) );
}

// A history (--every-s) of a slope that stays at rest: a search at the
// last stage's start and every 0.5 s of it, each at the closed-form FS.
TEST( FosCli, history_searches_every_interval_of_the_last_stage )
{
    const auto dir = mpm_test::freshTempDir( "fos_cli_history" );
    std::string text = mpm_test::infiniteSlopeCase( false, 0.5 );
    std::string rest = text.substr( text.find( "[[stages]]" ) );
    for ( const auto& [from, to] :
          std::vector<std::pair<std::string, std::string>>{
              { "\"gravity\"", "\"rest\"" },
              { "quasi_static", "dynamic" },
              { "duration_s = 10.0", "duration_s = 1.0" } } )
        rest.replace( rest.find( from ), from.size(), to );
    const auto case_file = mpm_test::writeCase( dir, text + rest );
    const auto out = dir / "history";
    const nlohmann::json j = runFosCli( case_file.string() + " --every-s 0.5",
                                        out, 2.35, "fos_history.json" );
    EXPECT_EQ( j.at( "stage" ), "rest" );
    const auto& rows = j.at( "rows" );
    ASSERT_EQ( rows.size(), 3u );
    const double exact = mpm_test::infiniteSlopeFactor( false );
    for ( std::size_t k = 0; k < rows.size(); ++k )
    {
        const auto& row = rows[k];
        EXPECT_NEAR( row.at( "stage_time_s" ).get<double>(), 0.5 * k, 1e-9 );
        ASSERT_EQ( row.at( "status" ), "found" );
        EXPECT_NEAR( row.at( "factor_of_safety" ).get<double>() / exact, 1.0,
                     0.03 );
        const auto folder = out / row.at( "folder" ).get<std::string>();
        EXPECT_TRUE( std::filesystem::exists( folder / "fos.json" ) );
    }
    EXPECT_EQ( rows[1].at( "folder" ), "t_0000.50" );
    EXPECT_TRUE( std::filesystem::exists( out / "states.h5" ) );
    EXPECT_FALSE( std::filesystem::exists( out / "states.h5.partial" ) );
}

TEST( FosCli, bad_input_exits_2_before_any_work )
{
    const auto dir = mpm_test::freshTempDir( "fos_cli_bad" );
    const std::string case_file =
        std::string( RAINSLIDE_CASES_DIR ) + "/fos_griffiths_lane.toml";
    auto result = mpm_test::runCommand( "fos " + case_file + " --out " +
                                        ( dir / "a" ).string() +
                                        " --min-factor 3 --max-factor 2" );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE( result.output.find( "--min-factor" ), std::string::npos );
    result = mpm_test::runCommand(
        "fos " + case_file + " --out " + ( dir / "b" ).string() +
        " --set materials[0].friction_angle_deg=-5" );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE( result.output.find( "friction_angle_deg" ), std::string::npos );
    result = mpm_test::runCommand( "fos " + case_file + " --out " +
                                   ( dir / "a" ).string() + " --restart " +
                                   ( dir / "none.h5" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    result = mpm_test::runCommand( "fos " + case_file + " --out " +
                                   ( dir / "a" ).string() + " --start -1" );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    // --every-s must be > 0 and cannot take a checkpoint's state.
    for ( const std::string& history :
          { std::string( " --every-s 0" ),
            " --every-s 1 --restart " + case_file } )
    {
        result = mpm_test::runCommand( "fos " + case_file + " --out " +
                                       ( dir / "a" ).string() + history );
        EXPECT_EQ( result.exit_code, 2 ) << result.output;
    }
    result = mpm_test::runCommand( "fos " + case_file + " --out /" );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_FALSE( std::filesystem::exists( dir / "a" ) );
    EXPECT_FALSE( std::filesystem::exists( dir / "b" ) );
}
