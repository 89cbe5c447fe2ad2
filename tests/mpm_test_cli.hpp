#ifndef MPM_TEST_CLI_HPP
#define MPM_TEST_CLI_HPP

// Helpers of the tests that run the rainslide binary (RAINSLIDE_BINARY).
#include <sys/wait.h>

#include <mpm_test_toml.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mpm_test
{
//! Exit code and output of one command.
struct CommandResult
{
    int exit_code;
    std::string output; //!< stdout and stderr
};

//! Runs `rainslide <args>`, its stdout and stderr going through `log`;
//! `wrapper` (e.g. "timeout -s INT 3 ") is put before the binary.
inline CommandResult runRainslide( const std::string& args,
                                   const std::filesystem::path& log,
                                   const std::string& wrapper = "" )
{
    const std::string command = wrapper + std::string( RAINSLIDE_BINARY ) +
                                " " + args + " > " + log.string() + " 2>&1";
    const int status = std::system( command.c_str() );
    std::ifstream in( log );
    std::stringstream text;
    text << in.rdbuf();
    return { WEXITSTATUS( status ), text.str() };
}

//! runRainslide with its log in the test temporary folder.
inline CommandResult runLogged( const std::string& args,
                                const std::string& log_name )
{
    return runRainslide( args, std::filesystem::path( ::testing::TempDir() ) /
                                   log_name );
}

//! runLogged with the log rainslide_<suite>.log of the running test's suite.
inline CommandResult runCommand( const std::string& args )
{
    const ::testing::TestInfo* test =
        ::testing::UnitTest::GetInstance()->current_test_info();
    return runLogged( args, std::string( "rainslide_" ) +
                                test->test_suite_name() + ".log" );
}

//! The arguments of `run` of `file` into `out` on the Serial backend,
//! followed by `extra`.
inline std::string runArgs( const std::filesystem::path& file,
                            const std::filesystem::path& out,
                            const std::string& extra = "" )
{
    return "run " + file.string() + " --out " + out.string() +
           " --backend serial" + extra;
}

//! An empty folder rainslide_<name> in the test temporary folder.
inline std::filesystem::path freshTempDir( const std::string& name )
{
    const std::filesystem::path dir =
        std::filesystem::path( ::testing::TempDir() ) / ( "rainslide_" + name );
    std::filesystem::remove_all( dir );
    std::filesystem::create_directories( dir );
    return dir;
}

//! Writes `text` to dir/case.toml and returns its path.
inline std::filesystem::path writeCase( const std::filesystem::path& dir,
                                        const std::string& text )
{
    const std::filesystem::path file = dir / "case.toml";
    std::ofstream( file ) << text;
    return file;
}

/*!
  \brief A dry 1 m x 2 m elastic block on a fixed base (0.25 m cells, 64
  points): the case text with `solver_extra` in [solver], followed by the
  [[stages]] tables of `stages`.
*/
inline std::string blockCaseText( const std::string& solver_extra,
                                  const std::string& stages )
{
    return "\n" + caseToml( "block" ) + gridToml( "0.25", "[8, 12]" ) +
           dryMaterialToml( "soil", "linear_elastic", "2000.0", "1.0e6",
                            "0.3" ) +
           soilBodyToml( "[[0.5, 0.0], [1.5, 0.0], [1.5, 2.0], [0.5, 2.0]]" ) +
           boundaryToml( "bottom", "fixed" ) + "[solver]\n" + solver_extra +
           "\n" + stages;
}

//! The test block with one dynamic stage of `duration_s` (snapshots every
//! 0.02 s) and a probe near its top sampled every 0.01 s.
inline std::string probedBlockCaseText( const std::string& duration_s )
{
    return blockCaseText( "", "\n" +
                                  stageToml( "load", "dynamic", duration_s ) +
                                  "snapshot_interval_s = 0.02\n[probes]\n"
                                  "interval_s = 0.01\npoints = [ { name = "
                                  "\"top\", position_m = [1.0, 1.9] } ]\n" );
}

//! The 0.5 m x 2 m column of saturatedColumnCaseText as polygon_m text.
inline const char* const column_polygon =
    "[[0.0, 0.0], [0.5, 0.0], [0.5, 2.0], [0.0, 2.0]]";

/*!
  \brief A saturated elastic column 0.5 m x 2 m on a fixed base (cells of
  0.5 m, grid up to 2.5 m, 16 points) named `name`, followed by the
  [[stages]] tables of `stages`.
*/
inline std::string saturatedColumnCaseText( const std::string& name,
                                            const std::string& stages )
{
    return "\n" + caseToml( name, "saturated" ) + gridToml( "0.5", "[1, 5]" ) +
           twoPhaseSoilToml( "2650.0", "1.0e-12", "1.0e7", "0.3" ) +
           soilBodyToml( column_polygon ) + boundaryToml( "bottom", "fixed" ) +
           stages;
}

//! Expects `result` to have exited with `exit_code` and its output to
//! contain `fragment`.
inline void expectExit( const CommandResult& result, const int exit_code,
                        const std::string& fragment )
{
    EXPECT_EQ( result.exit_code, exit_code ) << result.output;
    EXPECT_NE( result.output.find( fragment ), std::string::npos )
        << result.output;
}

} // namespace mpm_test

#endif // MPM_TEST_CLI_HPP
