#ifndef MPM_TEST_CASE_READER_HPP
#define MPM_TEST_CASE_READER_HPP

// Helpers of the case reader tests (tst_case_reader.cpp): two-phase variants
// of the minimal case, the errors of a case text, the expectation lines of
// a bad case file.
#include <mpm_test_minimal_case.hpp>

#include <io/mpm_case_reader.hpp>

#include <fstream>
#include <string>

namespace mpm_test
{
namespace case_reader
{
// The minimal case as a two-phase analysis; retention is appended to the
// material table (unsaturated analyses).
inline std::string twoPhaseCase( const std::string& analysis,
                                 const std::string& retention = "" )
{
    std::string text = minimal_case;
    text.replace( text.find( "[grid]" ), 0,
                  "analysis = \"" + analysis + "\"\n" );
    text.replace( text.find( "density_kg_per_m3 = 2000.0" ), 26,
                  "solid_density_kg_per_m3 = 2650.0\nporosity = 0.4\n"
                  "permeability_m2 = 1.0e-12" );
    text.replace( text.find( "[[bodies]]" ), 0, retention );
    return text;
}

//! The error lines of an invalid case ("" if it is valid).
inline std::string errorsOf( const std::string& text )
{
    try
    {
        mpm::parseCase( text, "x.toml" );
    }
    catch ( const mpm::CaseError& e )
    {
        return e.what();
    }
    return "";
}

//! The text after "# <tag>: " on a line of the comment block that opens
//! `file` ("" if there is none).
inline std::string headerValue( const std::string& file,
                                const std::string& tag )
{
    std::ifstream in( file );
    std::string line;
    const std::string prefix = "# " + tag + ": ";
    while ( std::getline( in, line ) && line.rfind( "#", 0 ) == 0 )
        if ( line.rfind( prefix, 0 ) == 0 )
            return line.substr( prefix.size() );
    return "";
}

} // namespace case_reader
} // namespace mpm_test

#endif // MPM_TEST_CASE_READER_HPP
