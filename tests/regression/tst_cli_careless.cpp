// The CLI used carelessly: `check` refuses what `run` refuses before its
// first step; an output folder that is read-only, in use by another run or
// among the case files is refused (exit 2) before any work; probes count in
// the output budget; Ctrl-C during set-up ends with exit 130, and a run that
// inherited an ignored SIGINT keeps ignoring it; an error of a --set value
// is reported before the errors it causes.
#include <mpm_test_cli.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

using mpm_test::runCommand;
using mpm_test::writeCase;

//! The test block with one dynamic stage of `duration_s`.
std::string blockCase( const std::string& solver_extra,
                       const std::string& duration_s = "0.2",
                       const std::string& extra = "" )
{
    return mpm_test::blockCaseText(
        solver_extra,
        "\n" + mpm_test::stageToml( "load", "dynamic", duration_s ) + extra );
}

//! `rainslide <args>` started in the background, stdout and stderr to
//! `log`; `ignore_sigint` starts it with SIGINT ignored (a background job).
pid_t spawnRainslide( const std::string& args, const fs::path& log,
                      const bool ignore_sigint = false )
{
    const pid_t pid = ::fork();
    if ( pid == 0 )
    {
        if ( ignore_sigint )
            std::signal( SIGINT, SIG_IGN );
        const int fd =
            ::open( log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644 );
        ::dup2( fd, 1 );
        ::dup2( fd, 2 );
        const std::string command =
            "exec " + std::string( RAINSLIDE_BINARY ) + " " + args;
        ::execl( "/bin/sh", "sh", "-c", command.c_str(),
                 static_cast<char*>( nullptr ) );
        ::_exit( 127 );
    }
    return pid;
}

//! True once `pid` runs the rainslide binary (not the forked test process
//! before its exec, whose masks are the test's) and its /proc/<pid>/status
//! mask `field` ("SigCgt:" caught, "SigIgn:" ignored) holds SIGINT, or
//! false after `timeout_s`.
bool waitForSigint( const pid_t pid, const std::string& field,
                    const double timeout_s )
{
    const std::string proc = "/proc/" + std::to_string( pid );
    std::error_code error;
    const fs::path binary = fs::canonical( RAINSLIDE_BINARY, error );
    const auto end = std::chrono::steady_clock::now() +
                     std::chrono::duration<double>( timeout_s );
    while ( std::chrono::steady_clock::now() < end )
    {
        if ( fs::read_symlink( proc + "/exe", error ) != binary )
        {
            std::this_thread::sleep_for( std::chrono::milliseconds( 2 ) );
            continue;
        }
        std::ifstream status( proc + "/status" );
        std::string line;
        while ( std::getline( status, line ) )
            if ( line.rfind( field, 0 ) == 0 &&
                 ( std::stoull( line.substr( field.size() ), nullptr, 16 ) &
                   ( 1ull << ( SIGINT - 1 ) ) ) )
                return true;
        std::this_thread::sleep_for( std::chrono::milliseconds( 2 ) );
    }
    return false;
}

std::string readAll( const fs::path& file )
{
    std::ifstream in( file );
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

//---------------------------------------------------------------------------//
// A fixed time step above the stable limit: `run` refused it after the
// simulation was built (exit 1), `check` passed it.
TEST( CliCareless, check_refuses_a_time_step_above_the_stable_limit )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_dt" );
    const fs::path file = writeCase( dir, blockCase( "" ) );
    for ( const std::string dt : { "1.0", "1e300" } )
    {
        SCOPED_TRACE( dt );
        const std::string set = " --set solver.dt_s=" + dt;
        mpm_test::expectExit( runCommand( "check " + file.string() + set ), 2,
                              "exceeds the stable limit" );
        const auto run = runCommand(
            mpm_test::runArgs( file, dir / "out", " --quiet" + set ) );
        mpm_test::expectExit( run, 2, "exceeds the stable limit" );
        EXPECT_FALSE( fs::exists( dir / "out" ) );
    }
}

//---------------------------------------------------------------------------//
// A read-only file system (a tmpfs mounted read-only in a user namespace).
TEST( CliCareless, read_only_output_folder_is_refused )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_readonly" );
    const fs::path file = writeCase( dir, blockCase( "" ) );
    const fs::path out = dir / "readonly";
    fs::create_directories( out );
    const fs::path log = dir / "log.txt";
    if ( std::system( ( "unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs " +
                        out.string() + "' > /dev/null 2>&1" )
                          .c_str() ) != 0 )
        GTEST_SKIP() << "no user namespaces to mount a read-only folder in";
    const std::string command =
        "unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs " + out.string() +
        " && exec " + RAINSLIDE_BINARY + " " +
        mpm_test::runArgs( file, out, " --quiet" ) + "' > " + log.string() +
        " 2>&1";
    const int status = std::system( command.c_str() );
    mpm_test::expectExit( { WEXITSTATUS( status ), readAll( log ) }, 2,
                          "the output folder '" + out.string() +
                              "' is not writable (Read-only file system)" );
}

//---------------------------------------------------------------------------//
// A second run into the folder of a running one is refused at once, naming
// the first; the lock of a killed run does not block the next.
TEST( CliCareless, a_second_run_into_a_folder_in_use_is_refused )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_lock" );
    const fs::path file = writeCase( dir, blockCase( "", "1000.0" ) );
    const fs::path out = dir / "out";
    const pid_t first = spawnRainslide(
        mpm_test::runArgs( file, out, " --quiet --max-steps 0" ),
        dir / "first.log" );
    ASSERT_GT( first, 0 );
    // Wait for the first run to start stepping (it has written a snapshot).
    for ( int k = 0; k < 1000 && !fs::exists( out / "particles.h5.partial" );
          ++k )
        std::this_thread::sleep_for( std::chrono::milliseconds( 10 ) );
    const auto second =
        runCommand( mpm_test::runArgs( file, out, " --quiet" ) );
    ::kill( first, SIGKILL );
    int status = 0;
    ::waitpid( first, &status, 0 );
    mpm_test::expectExit( second, 2,
                          "the output folder '" + out.string() +
                              "' is in use by another rainslide run (process " +
                              std::to_string( first ) );
    const fs::path quick = writeCase( dir, blockCase( "", "0.02" ) );
    mpm_test::expectExit(
        runCommand( mpm_test::runArgs( quick, out, " --quiet" ) ), 0,
        "completed" );
    EXPECT_FALSE( fs::exists( out / ".rainslide.lock" ) );
}

//---------------------------------------------------------------------------//
TEST( CliCareless, output_folder_among_the_case_files_is_refused )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_case_folder" );
    const fs::path file = writeCase( dir, blockCase( "", "0.02" ) );
    fs::create_directories( dir / "cases" );
    std::ofstream( dir / "cases" / "other.toml" ) << "\n";
    fs::create_directory_symlink( dir, dir / "link" );
    const auto refused = [&]( const fs::path& out, const std::string& why )
    {
        SCOPED_TRACE( out.string() );
        const auto result =
            runCommand( mpm_test::runArgs( file, out, " --quiet" ) );
        mpm_test::expectExit( result, 2,
                              "expected a folder of its own for the results, "
                              "found " +
                                  why );
        EXPECT_FALSE( fs::exists( out / "particles.h5" ) );
        EXPECT_FALSE( fs::exists( out / "metrics.json" ) );
    };
    refused( dir, "the folder of the case file" );
    refused( dir / "link", "the folder of the case file" );
    refused( dir / "cases", "a folder that holds case files" );
}

//---------------------------------------------------------------------------//
// 2,000 probes every 1 ms: their rows count in the estimated output.
TEST( CliCareless, probes_count_in_the_output_budget )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_probes" );
    std::string probes = "[probes]\ninterval_s = 0.001\npoints = [\n";
    for ( int k = 0; k < 2000; ++k )
        probes += "{ name = \"p" + std::to_string( k ) +
                  "\", position_m = [1.0, " +
                  std::to_string( 0.1 + 1.8 * k / 2000.0 ) + "] },\n";
    probes += "]\n";
    const fs::path file = writeCase( dir, blockCase( "", "1.0", probes ) );
    const auto check =
        runCommand( "check " + file.string() + " --max-output-gb 0.01" );
    mpm_test::expectExit( check, 2,
                          "the run exceeds the budget: estimated output (GB)" );
    mpm_test::expectExit( check, 2, "rows of probes.csv" );
}

//---------------------------------------------------------------------------//
// SIGINT once the handler is installed, while the case is still being
// checked (600 probes, each tested against 288,000 points: seconds): exit
// 130, not killed by the signal, nothing written.
TEST( CliCareless, interrupt_during_set_up_exits_130 )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_setup" );
    std::string probes = "[probes]\ninterval_s = 0.05\npoints = [\n";
    for ( int k = 0; k < 600; ++k )
        probes += "{ name = \"p" + std::to_string( k ) + "\", position_m = [" +
                  std::to_string( 0.1 + 0.1 * ( k % 25 ) ) + ", " +
                  std::to_string( 0.1 + 0.08 * ( k / 25 ) ) + "] },\n";
    probes += "]\n";
    const std::string text =
        "\n" + mpm_test::caseToml( "big" ) +
        mpm_test::gridToml( "0.01", "[300, 300]" ) +
        mpm_test::dryMaterialToml( "soil", "linear_elastic", "2000.0", "1.0e6",
                                   "0.3" ) +
        mpm_test::soilBodyToml(
            "[[0.0, 0.0], [3.0, 0.0], [3.0, 2.4], [0.0, 2.4]]" ) +
        mpm_test::boundaryToml( "bottom", "fixed" ) + "\n" +
        mpm_test::stageToml( "load", "dynamic", "0.1" ) + probes;
    const fs::path file = writeCase( dir, text );
    const fs::path out = dir / "out";
    const pid_t pid = spawnRainslide(
        mpm_test::runArgs( file, out, " --quiet" ), dir / "run.log" );
    ASSERT_GT( pid, 0 );
    waitForSigint( pid, "SigCgt:", 0.5 );
    ::kill( pid, SIGINT );
    int status = 0;
    ::waitpid( pid, &status, 0 );
    const std::string log = readAll( dir / "run.log" );
    ASSERT_TRUE( WIFEXITED( status ) )
        << "killed by signal " << WTERMSIG( status ) << "\n"
        << log;
    EXPECT_EQ( WEXITSTATUS( status ), 130 ) << log;
    EXPECT_NE( log.find( "interrupted during set-up" ), std::string::npos )
        << log;
    EXPECT_FALSE( fs::exists( out / "particles.h5" ) );
}

// A run started with SIGINT ignored (a background job of a shell) runs to
// its end through any number of SIGINTs.
TEST( CliCareless, inherited_ignored_sigint_stays_ignored )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_ignored" );
    const fs::path file = writeCase( dir, blockCase( "", "200.0" ) );
    const pid_t pid =
        spawnRainslide( mpm_test::runArgs( file, dir / "out", " --quiet" ),
                        dir / "run.log", true );
    ASSERT_GT( pid, 0 );
    // The child ignores SIGINT before it starts rainslide.
    ASSERT_TRUE( waitForSigint( pid, "SigIgn:", 5.0 ) );
    int status = 0;
    int signals = 0;
    while ( ::waitpid( pid, &status, WNOHANG ) == 0 )
    {
        ::kill( pid, SIGINT );
        ++signals;
        std::this_thread::sleep_for( std::chrono::milliseconds( 20 ) );
    }
    const std::string log = readAll( dir / "run.log" );
    ASSERT_TRUE( WIFEXITED( status ) ) << log;
    EXPECT_EQ( WEXITSTATUS( status ), 0 ) << log;
    EXPECT_GT( signals, 3 );
}

//---------------------------------------------------------------------------//
// A control character in a --set name: the override's own error first, then
// the unknown material it leads to.
TEST( CliCareless, set_error_is_reported_before_what_it_causes )
{
    const fs::path dir = mpm_test::freshTempDir( "careless_set" );
    const fs::path file = writeCase( dir, blockCase( "" ) );
    const auto result =
        runCommand( "check " + file.string() +
                    " --set 'materials[0].name=\"sand\\u0000x\"'" );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    const auto cause = result.output.find( "key 'materials[0].name'" );
    const auto effect = result.output.find( "unknown material" );
    ASSERT_NE( cause, std::string::npos ) << result.output;
    EXPECT_LT( cause, effect ) << result.output;
}

} // namespace
