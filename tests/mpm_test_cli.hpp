#ifndef MPM_TEST_CLI_HPP
#define MPM_TEST_CLI_HPP

// Helpers of the tests that run the rainslide binary (RAINSLIDE_BINARY).
#include <sys/wait.h>

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

//! Runs `rainslide <args>`, its stdout and stderr going through `log`.
inline CommandResult runRainslide( const std::string& args,
                                   const std::filesystem::path& log )
{
    const std::string command = std::string( RAINSLIDE_BINARY ) + " " + args +
                                " > " + log.string() + " 2>&1";
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
    return R"(
[case]
name = "block"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.25
cells = [8, 12]
[[materials]]
name = "soil"
model = "linear_elastic"
density_kg_per_m3 = 2000.0
youngs_modulus_pa = 1.0e6
poisson_ratio = 0.3
[[bodies]]
material = "soil"
polygon_m = [[0.5, 0.0], [1.5, 0.0], [1.5, 2.0], [0.5, 2.0]]
[[boundaries]]
where = "bottom"
condition = "fixed"
[solver]
)" + solver_extra +
           "\n" + stages;
}

//! The test block with one dynamic stage of `duration_s` (snapshots every
//! 0.02 s) and a probe near its top sampled every 0.01 s.
inline std::string probedBlockCaseText( const std::string& duration_s )
{
    return blockCaseText( "", R"(
[[stages]]
name = "load"
type = "dynamic"
duration_s = )" + duration_s + R"(
snapshot_interval_s = 0.02
[probes]
interval_s = 0.01
points = [ { name = "top", position_m = [1.0, 1.9] } ]
)" );
}

/*!
  \brief A saturated elastic column 0.5 m x 2 m on a fixed base (cells of
  0.5 m, grid up to 2.5 m, 16 points) named `name`, followed by the
  [[stages]] tables of `stages`.
*/
inline std::string saturatedColumnCaseText( const std::string& name,
                                            const std::string& stages )
{
    return R"(
[case]
name = ")" +
           name + R"("
analysis = "saturated"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.5
cells = [1, 5]
[[materials]]
name = "soil"
model = "linear_elastic"
solid_density_kg_per_m3 = 2650.0
porosity = 0.3
permeability_m2 = 1.0e-12
youngs_modulus_pa = 1.0e7
poisson_ratio = 0.3
[[bodies]]
material = "soil"
polygon_m = [[0.0, 0.0], [0.5, 0.0], [0.5, 2.0], [0.0, 2.0]]
[[boundaries]]
where = "bottom"
condition = "fixed"
)" + stages;
}

} // namespace mpm_test

#endif // MPM_TEST_CLI_HPP
