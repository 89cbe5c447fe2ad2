// JSON output files (io/mpm_json_output.hpp): written valid and atomically,
// a symlink at the temporary file is not followed.
#include <io/mpm_json_output.hpp>
#include <mpm_test_temp_dir.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

using mpm_test::listDir;
using mpm_test::TempDir;

} // namespace

//---------------------------------------------------------------------------//
TEST( JsonOutput, writes_valid_json_atomically )
{
    TempDir tmp;
    const fs::path path = tmp.path / "summary.json";
    const nlohmann::json value = { { "case", "slope" },
                                   { "time_s", 1.0 / 3.0 },
                                   { "stages", { "gravity", "rain" } } };
    mpm::writeJsonAtomically( path.string(), value );
    mpm::writeJsonAtomically( path.string(), value ); // replaces

    std::ifstream in( path );
    EXPECT_EQ( nlohmann::json::parse( in ), value );
    EXPECT_EQ( listDir( tmp.path ),
               std::vector<std::string>{ "summary.json" } );

    const std::string bad = ( tmp.path / "missing" / "x.json" ).string();
    try
    {
        mpm::writeJsonAtomically( bad, value );
        FAIL() << "expected an exception";
    }
    catch ( const std::runtime_error& e )
    {
        EXPECT_NE( std::string( e.what() ).find( bad ), std::string::npos )
            << e.what();
    }
}

//---------------------------------------------------------------------------//
// Output safety (issue 12): a symlink planted at a temporary name is
// removed, never followed; a failed write (disk full) is never published.
//---------------------------------------------------------------------------//
TEST( JsonOutput, symlink_at_temporary_file_is_not_followed )
{
    TempDir tmp;
    const fs::path target = tmp.path / "precious.txt";
    std::ofstream( target ) << "precious";
    const fs::path path = tmp.path / "metrics.json";
    fs::create_symlink( target, path.string() + ".tmp." +
                                    std::to_string( ::getpid() ) );
    mpm::writeJsonAtomically( path.string(), { { "status", "completed" } } );
    std::ifstream in( target );
    std::string text;
    std::getline( in, text );
    EXPECT_EQ( text, "precious" );
    EXPECT_TRUE( fs::is_regular_file( path ) );
}
