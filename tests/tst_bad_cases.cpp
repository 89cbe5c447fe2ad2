// The case reader against every file in tests/data/bad_cases/.
#include <io/mpm_case_reader.hpp>
#include <mpm_test_case_reader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#ifndef RAINSLIDE_TEST_DATA_DIR
#define RAINSLIDE_TEST_DATA_DIR "/work/main/tests/data"
#endif

namespace
{
using mpm_test::case_reader::headerValue;

//---------------------------------------------------------------------------//
// Case reader: every file in data/bad_cases/ must be rejected. Its first
// lines hold the expectation:
//   # expect: <fragment of the first error line>
//   # expect-line: <line of the first error>
//---------------------------------------------------------------------------//
TEST( CaseReader, rejects_every_bad_case )
{
    std::vector<std::string> files;
    for ( const auto& entry : std::filesystem::directory_iterator(
              RAINSLIDE_TEST_DATA_DIR "/bad_cases" ) )
        if ( entry.path().extension() == ".toml" )
            files.push_back( entry.path().string() );
    std::sort( files.begin(), files.end() );
    EXPECT_GE( files.size(), 60u );

    for ( const auto& file : files )
    {
        SCOPED_TRACE( file );
        const std::string fragment = headerValue( file, "expect" );
        const std::string line = headerValue( file, "expect-line" );
        ASSERT_FALSE( fragment.empty() ) << "no '# expect: ' line";
        ASSERT_FALSE( line.empty() ) << "no '# expect-line: ' line";
        try
        {
            mpm::readCaseFile( file );
            ADD_FAILURE() << "accepted a bad case";
        }
        catch ( const mpm::CaseError& e )
        {
            const std::string msg = e.what();
            const std::string first = msg.substr( 0, msg.find( '\n' ) );
            EXPECT_EQ( first.rfind( file + ":" + line + ":", 0 ), 0u )
                << "first error: " << first;
            EXPECT_NE( first.find( fragment ), std::string::npos )
                << "first error: " << first;
        }
    }
}

} // namespace
