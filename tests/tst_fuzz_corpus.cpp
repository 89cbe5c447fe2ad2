// Replay of tests/fuzz/corpus/: inputs of the fuzz target
// tests/fuzz/fuzz_case_check.cpp (scripts/fuzz.sh) that found a bug, and a
// few others kept for their coverage. Each goes through the same path
// (mpm::Fuzz::checkInput: the bytes as case.toml in a private folder, then
// mpm::checkCase, as `rainslide check`) and must end within 5 s with only a
// CaseError, if anything, escaping. Its sidecar NAME.expect states the
// outcome, one line each:
//   ok                 the case is accepted
//   error: TEXT        TEXT is part of the error report, in which the
//                      folder is left out ("case.toml:1:2: error: ...")
//   # ...              a comment (what the input found)
#include <fuzz/mpm_fuzz_case.hpp>

#include <gtest/gtest.h>

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

namespace
{
namespace fs = std::filesystem;

constexpr auto time_limit = std::chrono::seconds( 5 );
//! The fuzzer's -max_len (scripts/fuzz.sh).
constexpr std::uintmax_t max_input_bytes = 65536;

std::string readBytes( const fs::path& path )
{
    std::ifstream in( path, std::ios::binary );
    return std::string( std::istreambuf_iterator<char>( in ),
                        std::istreambuf_iterator<char>() );
}

//! The expectation of one input, from its sidecar.
struct Expectation
{
    bool ok = false;
    std::vector<std::string> errors;
};

Expectation readExpectation( const fs::path& sidecar )
{
    Expectation expect;
    std::ifstream in( sidecar );
    std::string line;
    while ( std::getline( in, line ) )
    {
        if ( line.empty() || line[0] == '#' )
            continue;
        if ( line == "ok" )
            expect.ok = true;
        else if ( line.rfind( "error: ", 0 ) == 0 )
            expect.errors.push_back( line.substr( 7 ) );
        else
            ADD_FAILURE() << sidecar << ": unknown line '" << line << "'";
    }
    return expect;
}

//! One input checked on its own thread, so that a hang fails the test
//! instead of stopping the suite (the thread is then left behind).
struct Replay
{
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    mpm::Fuzz::Outcome outcome;
    std::string escaped; //!< an exception other than CaseError
};

std::string removeAll( std::string text, const std::string& part )
{
    for ( std::size_t at = text.find( part ); at != std::string::npos;
          at = text.find( part, at ) )
        text.erase( at, part.size() );
    return text;
}

TEST( FuzzCorpus, every_input_ends_as_its_sidecar_states )
{
    std::vector<fs::path> inputs;
    for ( const auto& entry :
          fs::directory_iterator( RAINSLIDE_FUZZ_CORPUS_DIR ) )
        if ( entry.is_regular_file() && entry.path().extension() != ".expect" )
            inputs.push_back( entry.path() );
    std::sort( inputs.begin(), inputs.end() );
    ASSERT_GE( inputs.size(), 1u );

    for ( const fs::path& input : inputs )
    {
        SCOPED_TRACE( input.string() );
        fs::path sidecar = input;
        sidecar += ".expect";
        if ( !fs::exists( sidecar ) )
        {
            ADD_FAILURE() << "no sidecar " << sidecar;
            continue;
        }
        EXPECT_LE( fs::file_size( input ), max_input_bytes );
        const Expectation expect = readExpectation( sidecar );
        EXPECT_NE( expect.ok, !expect.errors.empty() )
            << sidecar << ": expected 'ok' or 'error: ...' lines";

        std::string folder =
            ( fs::temp_directory_path() / "rainslide-corpus-XXXXXX" ).string();
        ASSERT_NE( mkdtemp( folder.data() ), nullptr );
        auto replay = std::make_shared<Replay>();
        const auto start = std::chrono::steady_clock::now();
        std::thread(
            [replay, folder, bytes = readBytes( input )]()
            {
                mpm::Fuzz::Outcome outcome;
                std::string escaped;
                try
                {
                    outcome = mpm::Fuzz::checkInput( folder, bytes );
                }
                catch ( const std::exception& e )
                {
                    escaped =
                        std::string( typeid( e ).name() ) + ": " + e.what();
                }
                catch ( ... )
                {
                    escaped = "an exception not derived from std::exception";
                }
                std::lock_guard<std::mutex> lock( replay->mutex );
                replay->outcome = outcome;
                replay->escaped = escaped;
                replay->done = true;
                replay->finished.notify_all();
            } )
            .detach();
        std::unique_lock<std::mutex> lock( replay->mutex );
        if ( !replay->finished.wait_for( lock, time_limit,
                                         [&] { return replay->done; } ) )
        {
            ADD_FAILURE() << "did not return within 5 s (left running; its "
                             "folder "
                          << folder << " is kept)";
            continue;
        }
        const double seconds = std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - start )
                                   .count();
        std::error_code ignored;
        fs::remove_all( folder, ignored );
        EXPECT_TRUE( replay->escaped.empty() )
            << "an exception other than CaseError escaped: " << replay->escaped;
        if ( !replay->escaped.empty() )
            continue;
        const std::string report =
            removeAll( replay->outcome.text, folder + "/" );
        EXPECT_EQ( replay->outcome.ok, expect.ok )
            << ( expect.ok ? "refused: " : "accepted; report: " ) << report;
        for ( const std::string& error : expect.errors )
            EXPECT_NE( report.find( error ), std::string::npos )
                << "expected '" << error << "' in: " << report;
        EXPECT_LT( seconds, 5.0 );
    }
}

} // namespace
