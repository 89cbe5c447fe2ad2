// Hostile and careless case files: each must be refused within seconds and
// bounded memory, with a message naming the file, the key and the limit
// (issue 12; each reproduced a crash or hang on 226a27a).
#include <io/mpm_case_reader.hpp>
#include <mpm_test_minimal_case.hpp>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace
{
namespace fs = std::filesystem;

//! The minimal case's block, linear elastic.
const std::string small_case =
    mpm_test::dryBlockCase( "small", "linear_elastic", "" );

//! The error text of `read` (fails the test if it accepts the case), and
//! its time in seconds.
template <class Read>
std::string errorsOfRead( const Read& read, double& seconds )
{
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try
    {
        read();
        ADD_FAILURE() << "accepted the case";
    }
    catch ( const mpm::CaseError& e )
    {
        message = e.what();
    }
    seconds = std::chrono::duration<double>( std::chrono::steady_clock::now() -
                                             start )
                  .count();
    return message;
}

//! The error text of a case text, and its time in seconds.
std::string errorsOf( const std::string& text, double& seconds,
                      const std::string& file = "x.toml" )
{
    return errorsOfRead( [&] { mpm::parseCase( text, file ); }, seconds );
}

//! The error text of a case file, and its time in seconds.
std::string errorsOfFile( const fs::path& file, double& seconds )
{
    return errorsOfRead( [&] { mpm::readCaseFile( file.string() ); }, seconds );
}

fs::path freshDir( const std::string& name )
{
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / ( "rainslide_limits_" + name );
    fs::remove_all( dir );
    fs::create_directories( dir );
    return dir;
}

void writeFile( const fs::path& path, const std::string& text )
{
    std::ofstream( path ) << text;
}

//! small_case with text inserted before its [[stages]] table.
std::string withBeforeStages( const std::string& text )
{
    std::string result = small_case;
    result.insert( result.find( "[[stages]]" ), text );
    return result;
}

//---------------------------------------------------------------------------//
// Nesting and sizes, before toml++ parses (it overflowed the stack).
//---------------------------------------------------------------------------//
TEST( CaseLimits, deep_dotted_key_is_refused_before_parsing )
{
    std::string key = "a";
    for ( int k = 0; k < 35000; ++k )
        key += ".a";
    double seconds = 0.0;
    const std::string msg =
        errorsOf( withBeforeStages( key + " = 1\n" ), seconds );
    EXPECT_EQ( msg.rfind( "x.toml:17:", 0 ), 0u ) << msg;
    EXPECT_NE( msg.find( "nested deeper than 64 levels" ), std::string::npos )
        << msg;
    EXPECT_LT( seconds, 2.0 );
}

TEST( CaseLimits, deep_arrays_and_inline_tables_are_refused )
{
    double seconds = 0.0;
    const std::string arrays = "x = " + std::string( 40000, '[' ) + "\n";
    EXPECT_NE( errorsOf( withBeforeStages( arrays ), seconds )
                   .find( "nested deeper than 64 levels" ),
               std::string::npos );
    std::string tables = "x = ";
    for ( int k = 0; k < 40000; ++k )
        tables += "{a=";
    EXPECT_NE( errorsOf( withBeforeStages( tables + "\n" ), seconds )
                   .find( "nested deeper than 64 levels" ),
               std::string::npos );
    // Brackets and dots inside strings and comments do not count.
    std::string quoted = small_case;
    quoted.replace( quoted.find( "name = \"settle\"" ), 15,
                    "name = \"" + std::string( 100, '[' ) + "\" # " +
                        std::string( 100, '{' ) + std::string( 100, '.' ) );
    EXPECT_NO_THROW( mpm::parseCase( quoted, "quoted.toml" ) );
}

TEST( CaseLimits, long_unknown_key_gets_no_quadratic_suggestion )
{
    double seconds = 0.0;
    std::string text = small_case;
    text.insert( 0, std::string( 40000, 'q' ) + " = 1\n" );
    const std::string msg = errorsOf( text, seconds );
    EXPECT_NE( msg.find( "unknown key" ), std::string::npos ) << msg;
    EXPECT_NE( msg.find( "(40000 characters)" ), std::string::npos ) << msg;
    EXPECT_LT( msg.size(), 2000u );
    EXPECT_LT( seconds, 2.0 );
    // A typo of a long key is still suggested.
    text = small_case;
    text.replace( text.find( "youngs_modulus_pa" ), 17, "youngs_modulsu_pa" );
    EXPECT_NE(
        errorsOf( text, seconds ).find( "did you mean 'youngs_modulus_pa'?" ),
        std::string::npos );
}

TEST( CaseLimits, long_names_are_refused )
{
    double seconds = 0.0;
    std::string text = small_case;
    text.replace( text.find( "name = \"settle\"" ), 15,
                  "name = \"" + std::string( 70000, 's' ) + "\"" );
    const std::string msg = errorsOf( text, seconds );
    EXPECT_NE( msg.find( "key 'stages[0].name': expected a non-empty name of "
                         "at most 128 characters" ),
               std::string::npos )
        << msg;
    EXPECT_NE( msg.find( "(70000 characters)" ), std::string::npos ) << msg;
    EXPECT_LT( msg.size(), 2000u );
}

TEST( CaseLimits, polygon_with_too_many_vertices_is_refused_quickly )
{
    std::string polygon = "polygon_m = [";
    const int n = 100000;
    for ( int k = 0; k < n; ++k )
        polygon +=
            "[" + std::to_string( 5.0 + 4.0 * std::cos( k * 6.283185 / n ) ) +
            ", " + std::to_string( 5.0 + 4.0 * std::sin( k * 6.283185 / n ) ) +
            "], ";
    polygon += "]\n";
    std::string text = small_case;
    const auto at = text.find( "polygon_m" );
    text.replace( at, text.find( '\n', at ) + 1 - at, polygon );
    double seconds = 0.0;
    const std::string msg = errorsOf( text, seconds );
    EXPECT_NE( msg.find( "key 'bodies[0].polygon_m': expected an array of 3 "
                         "to 2000 points" ),
               std::string::npos )
        << msg;
    EXPECT_LT( seconds, 5.0 );
}

//---------------------------------------------------------------------------//
// Files: regular files only, bounded reads, include limits.
//---------------------------------------------------------------------------//
TEST( CaseLimits, case_file_must_be_a_regular_file )
{
    double seconds = 0.0;
    EXPECT_NE( errorsOfFile( "/dev/zero", seconds )
                   .find( "/dev/zero: error: cannot open the case file: "
                          "expected a readable regular file of at most "
                          "8388608 bytes, found a character device" ),
               std::string::npos );
    const fs::path dir = freshDir( "regular" );
    EXPECT_NE( errorsOfFile( dir, seconds ).find( "found a directory" ),
               std::string::npos );
    const fs::path big = dir / "big.toml";
    writeFile( big, std::string( 9u << 20, '#' ) );
    EXPECT_NE(
        errorsOfFile( big, seconds ).find( "found a file of 9437184 bytes" ),
        std::string::npos );
}

TEST( CaseLimits, unreadable_include_is_reported )
{
    if ( ::geteuid() == 0 )
        GTEST_SKIP() << "root reads every file";
    const fs::path dir = freshDir( "unreadable" );
    writeFile( dir / "secret.toml", "[case]\nname = \"x\"\n" );
    fs::permissions( dir / "secret.toml", fs::perms::none );
    writeFile( dir / "case.toml",
               "include = \"secret.toml\"\n" + std::string( small_case ) );
    double seconds = 0.0;
    EXPECT_NE( errorsOfFile( dir / "case.toml", seconds )
                   .find( "found a file that cannot be opened (Permission "
                          "denied)" ),
               std::string::npos );
}

TEST( CaseLimits, include_of_a_fifo_does_not_block )
{
    const fs::path dir = freshDir( "fifo" );
    ASSERT_EQ( ::mkfifo( ( dir / "pipe.toml" ).c_str(), 0600 ), 0 );
    writeFile( dir / "case.toml",
               "include = \"pipe.toml\"\n" + std::string( small_case ) );
    double seconds = 0.0;
    const std::string msg = errorsOfFile( dir / "case.toml", seconds );
    EXPECT_EQ( msg.rfind( ( dir / "case.toml" ).string() +
                              ":1:11: error: key 'include': cannot include '" +
                              ( dir / "pipe.toml" ).string() +
                              "': expected a readable regular file",
                          0 ),
               0u )
        << msg;
    EXPECT_NE( msg.find( "found a FIFO (named pipe)" ), std::string::npos );
}

TEST( CaseLimits, include_diamond_is_bounded_in_count )
{
    // Level k includes level k + 1 ten times: 10^5 files unbounded (a
    // diamond of 7 levels ran > 20 s).
    const fs::path dir = freshDir( "diamond" );
    for ( int level = 0; level < 5; ++level )
    {
        std::string list = "include = [";
        for ( int k = 0; k < 10; ++k )
            list += "\"level" + std::to_string( level + 1 ) + ".toml\", ";
        writeFile( dir / ( "level" + std::to_string( level ) + ".toml" ),
                   list + "]\n" );
    }
    writeFile( dir / "level5.toml", "[case]\nname = \"deep\"\n" );
    writeFile( dir / "case.toml",
               "include = \"level0.toml\"\n" + std::string( small_case ) );
    double seconds = 0.0;
    const std::string msg = errorsOfFile( dir / "case.toml", seconds );
    EXPECT_NE( msg.find( "expected at most 64 included files in all" ),
               std::string::npos )
        << msg;
    EXPECT_LT( seconds, 5.0 );
}

TEST( CaseLimits, include_total_size_is_bounded )
{
    // Three files of 7 MB each: each under the per-file limit, together
    // over the 16 MiB of a case.
    const fs::path dir = freshDir( "size" );
    const std::string padding = std::string( 7u << 20, '#' ) + "\n";
    writeFile( dir / "a.toml", padding );
    writeFile( dir / "b.toml", padding );
    writeFile( dir / "c.toml", padding );
    writeFile( dir / "case.toml",
               "include = [\"a.toml\", \"b.toml\", \"c.toml\"]\n" +
                   std::string( small_case ) );
    double seconds = 0.0;
    const std::string msg = errorsOfFile( dir / "case.toml", seconds );
    EXPECT_NE( msg.find( "cannot include '" + ( dir / "c.toml" ).string() ),
               std::string::npos )
        << msg;
}

TEST( CaseLimits, self_include_through_dot_slash_is_circular )
{
    const fs::path dir = freshDir( "itself" );
    std::string list = "include = [";
    for ( int k = 0; k < 10; ++k )
        list += "\"./case.toml\", \"sub/../case.toml\", ";
    fs::create_directories( dir / "sub" );
    writeFile( dir / "case.toml", list + "]\n" + std::string( small_case ) );
    double seconds = 0.0;
    const std::string msg = errorsOfFile( dir / "case.toml", seconds );
    EXPECT_NE( msg.find( "includes itself" ), std::string::npos ) << msg;
    EXPECT_LT( seconds, 2.0 );
}

} // namespace
