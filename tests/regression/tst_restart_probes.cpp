// probes.csv across restarts (issue 12): stopped after any step and
// restarted, a run records the same probe rows as an uninterrupted one (the
// next sample was once recomputed from the checkpoint's time, so a
// checkpoint at t = 1.2499999999999956 skipped the 1.25 sample; kept rows
// were compared by their 9-digit printed time).
#include <mpm_test_cli.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

using mpm_test::runCommand;

//! The time column of every row of a probes.csv.
std::vector<std::string> sampleTimes( const fs::path& csv )
{
    std::ifstream in( csv );
    std::string line;
    std::getline( in, line ); // header
    std::vector<std::string> times;
    while ( std::getline( in, line ) )
        times.push_back( line.substr( 0, line.find( ',' ) ) );
    return times;
}

TEST( RestartProbes, every_stop_keeps_every_sample )
{
    const fs::path dir = mpm_test::freshTempDir( "restart_probes" );
    // Snapshots every 0.02 s land steps on multiples of the 0.01 s probe
    // interval, up to round-off: checkpoints fall just below due times.
    const fs::path file =
        mpm_test::writeCase( dir, mpm_test::probedBlockCaseText( "0.1" ) );
    const std::string run =
        "run " + file.string() + " --backend serial --quiet --out ";
    ASSERT_EQ( runCommand( run + ( dir / "full" ).string() ).exit_code, 0 );
    const auto full = sampleTimes( dir / "full" / "probes.csv" );
    ASSERT_GE( full.size(), 10u );

    for ( int stop = 2; stop <= 20; ++stop )
    {
        SCOPED_TRACE( "stopped after " + std::to_string( stop ) + " steps" );
        const fs::path part = dir / ( "part" + std::to_string( stop ) );
        const auto stopped =
            runCommand( run + part.string() + " --stop-after-steps " +
                        std::to_string( stop ) );
        ASSERT_EQ( stopped.exit_code, 130 ) << stopped.output;
        const auto resumed = runCommand(
            "run " + file.string() + " --backend serial --quiet --restart " +
            ( part / "checkpoint.h5" ).string() );
        ASSERT_EQ( resumed.exit_code, 0 ) << resumed.output;
        EXPECT_EQ( sampleTimes( part / "probes.csv" ), full );
    }
}

} // namespace
