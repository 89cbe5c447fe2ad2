#ifndef MPM_TEST_TEMP_DIR_HPP
#define MPM_TEST_TEMP_DIR_HPP

// A fresh temporary folder and its listing, for the tests of the output
// files (tst_snapshot_writer.cpp, tst_json_output.cpp).
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace mpm_test
{
// A fresh folder under the GoogleTest temp dir, removed at scope exit.
struct TempDir
{
    std::filesystem::path path;
    TempDir()
    {
        std::string pattern = ::testing::TempDir() + "rainslide_io_XXXXXX";
        if ( ::mkdtemp( pattern.data() ) == nullptr )
            throw std::runtime_error( "mkdtemp failed" );
        path = pattern;
    }
    ~TempDir()
    {
        std::error_code ec;
        std::filesystem::remove_all( path, ec );
    }
};

inline std::vector<std::string> listDir( const std::filesystem::path& dir )
{
    std::vector<std::string> names;
    for ( const auto& entry : std::filesystem::directory_iterator( dir ) )
        names.push_back( entry.path().filename().string() );
    return names;
}

} // namespace mpm_test

#endif // MPM_TEST_TEMP_DIR_HPP
