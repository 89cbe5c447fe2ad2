#ifndef MPM_FUZZ_CASE_HPP
#define MPM_FUZZ_CASE_HPP

// One fuzz input through `rainslide check`'s path (mpm::checkCase), shared by
// the libFuzzer target (tests/fuzz/fuzz_case_check.cpp) and the replay of
// tests/fuzz/corpus/ in the normal suite (tests/tst_fuzz_corpus.cpp).
//
// An input is a case file. Its leading lines "#set KEY=VALUE" (TOML
// comments, so the case is unchanged by them) are also passed as --set
// overrides, in order, so the fuzzer reaches the override code too.

#include <io/mpm_case_reader.hpp>
#include <setup/mpm_case_check.hpp>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mpm
{
namespace Fuzz
{
//! How one input ended; anything else (another exception, a crash, a
//! sanitizer report, a hang) is a finding.
struct Outcome
{
    bool ok = false;  //!< checkCase accepted the case
    std::string text; //!< CaseError::what() or checkErrorReport()
};

//! The "#set " lines at the start of the input (at most 80 of them).
inline std::vector<std::string> leadingOverrides( std::string_view bytes )
{
    std::vector<std::string> overrides;
    constexpr std::string_view tag = "#set ";
    while ( overrides.size() < 80 && bytes.substr( 0, tag.size() ) == tag )
    {
        const std::size_t end = bytes.find( '\n' );
        overrides.emplace_back( bytes.substr(
            tag.size(), end == std::string_view::npos ? std::string_view::npos
                                                      : end - tag.size() ) );
        if ( end == std::string_view::npos )
            break;
        bytes.remove_prefix( end + 1 );
    }
    return overrides;
}

//! Write the input to folder/case.toml and check it as `rainslide check`
//! does (default budget). Throws what checkCase throws, except CaseError.
inline Outcome checkInput( const std::string& folder,
                           const std::string_view bytes )
{
    const std::string path = folder + "/case.toml";
    std::FILE* file = std::fopen( path.c_str(), "wb" );
    if ( !file )
        throw std::logic_error( "cannot create " + path );
    const bool written =
        std::fwrite( bytes.data(), 1, bytes.size(), file ) == bytes.size();
    if ( std::fclose( file ) != 0 || !written )
        throw std::logic_error( "cannot write " + path );

    Outcome outcome;
    try
    {
        const CaseCheck check =
            checkCase( path, leadingOverrides( bytes ), RunBudget() );
        outcome.ok = check.ok();
        outcome.text = checkErrorReport( check );
    }
    catch ( const CaseError& error )
    {
        outcome.text = error.what();
    }
    return outcome;
}

} // namespace Fuzz
} // namespace mpm

#endif // MPM_FUZZ_CASE_HPP
