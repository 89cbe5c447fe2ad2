// `rainslide run/check --set KEY=VALUE`: overrides of a case's keys,
// applied before the case is checked (Impl::applyOverrides).
#include <mpm_test_minimal_case.hpp>

#include <io/mpm_case_reader.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
//! The error text of a case with these overrides ("" if it is valid).
std::string errorOf( const std::vector<std::string>& overrides )
{
    try
    {
        mpm::parseCase( mpm_test::minimal_case, "case.toml", overrides );
    }
    catch ( const mpm::CaseError& error )
    {
        return error.what();
    }
    return "";
}

// A value replaced, a table created, an array element's key set, a
// material's, in order (the last one wins); recorded in the config.
TEST( CaseOverrides, set_keys_tables_and_array_elements )
{
    const std::vector<std::string> overrides = {
        "solver.courant_number=0.5", "stages[0].duration_s=3.5",
        "materials[0].friction_angle_deg=25.0", "case.name=\"renamed\"",
        "solver.courant_number=0.25" };
    const auto config =
        mpm::parseCase( mpm_test::minimal_case, "case.toml", overrides );
    EXPECT_DOUBLE_EQ( config.solver.courant_number, 0.25 );
    EXPECT_DOUBLE_EQ( config.stages[0].duration_s, 3.5 );
    EXPECT_DOUBLE_EQ( config.materials[0].friction_angle_deg, 25.0 );
    EXPECT_EQ( config.name, "renamed" );
    EXPECT_EQ( config.overrides, overrides );
    // The fingerprint (a checkpoint's identity) follows the overrides.
    const auto plain = mpm::parseCase( mpm_test::minimal_case, "case.toml" );
    EXPECT_NE( config.fingerprint, plain.fingerprint );
    EXPECT_TRUE( plain.overrides.empty() );
}

// The checks of the case apply to overridden values, and name the
// override; malformed overrides are refused with what was expected.
TEST( CaseOverrides, bad_overrides_are_refused_with_the_override_named )
{
    const auto expectError =
        []( const std::string& override, const std::string& part )
    {
        const std::string error = errorOf( { override } );
        EXPECT_NE( error.find( "--set " + override ), std::string::npos )
            << error;
        EXPECT_NE( error.find( part ), std::string::npos ) << error;
    };
    expectError( "solver.courant_number=5.0", "solver.courant_number" );
    expectError( "solver.courant_number=\"fast\"", "expected a number" );
    expectError( "solver.courant_number", "expected KEY=VALUE" );
    expectError( "solver.courant_number=fast", "not a TOML value" );
    expectError( "stages[3].duration_s=1.0", "past its 1 element(s)" );
    expectError( "grid.cell_size_m.x=1.0", "expected a table, found a value" );
    expectError( "case[0].name=\"x\"", "expected an array, found a table" );
    expectError( "solver..x=1", "expected a key name" );
    expectError( "stages[x].duration_s=1", "expected an array index" );
    expectError( "include=\"other.toml\"", "cannot be set" );
    expectError( "solver.bbar=" + std::string( 100, '[' ), "nest" );
    // An unknown key is the case reader's error, with its suggestion.
    const std::string unknown = errorOf( { "solver.courant_numbr=0.5" } );
    EXPECT_NE( unknown.find( "courant_number" ), std::string::npos ) << unknown;
    EXPECT_EQ( errorOf( { "solver.courant_number=0.5" } ), "" );
    EXPECT_NE( errorOf( std::vector<std::string>( 65, "case.name=\"a\"" ) )
                   .find( "at most 64 overrides" ),
               std::string::npos );
}

} // namespace
