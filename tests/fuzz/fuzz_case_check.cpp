// libFuzzer target: `rainslide check` on arbitrary bytes (scripts/fuzz.sh).
// Each input is written to case.toml in a private folder (made once per
// process with mkdtemp, removed at exit) and checked with mpm::checkCase;
// a CaseError is a normal outcome (bad input). Anything else is a finding:
// another exception escaping (aborts here), a crash, a sanitizer report, a
// hang beyond -timeout or memory beyond -rss_limit_mb.
#include <fuzz/mpm_fuzz_case.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>

namespace
{
std::string& folder()
{
    static std::string path;
    return path;
}

void removeFolder()
{
    std::error_code ignored;
    if ( !folder().empty() )
        std::filesystem::remove_all( folder(), ignored );
}

const std::string& privateFolder()
{
    if ( folder().empty() )
    {
        const char* tmp = std::getenv( "TMPDIR" );
        std::string pattern = std::string( tmp && *tmp ? tmp : "/tmp" ) +
                              "/rainslide-fuzz-XXXXXX";
        if ( !mkdtemp( pattern.data() ) )
        {
            std::perror( "fuzz_case_check: mkdtemp" );
            std::abort();
        }
        folder() = pattern;
        std::atexit( removeFolder );
    }
    return folder();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput( const std::uint8_t* data,
                                       std::size_t size )
{
    const std::string& dir = privateFolder();
    try
    {
        mpm::Fuzz::checkInput(
            dir,
            std::string_view( reinterpret_cast<const char*>( data ), size ) );
    }
    catch ( const std::exception& e )
    {
        std::fprintf( stderr,
                      "fuzz_case_check: an exception other than CaseError "
                      "escaped: %s: %s\n",
                      typeid( e ).name(), e.what() );
        std::abort();
    }
    catch ( ... )
    {
        std::fprintf( stderr,
                      "fuzz_case_check: a non-std exception escaped\n" );
        std::abort();
    }
    return 0;
}
