#include <io/mpm_case_fingerprint.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

namespace mpm
{
namespace
{
//! Keys that do not change the results of a run.
bool ignoredKey( const std::string& path )
{
    return path == "solver.checkpoint_interval_s";
}

//! A value as text: numbers in their shortest exact form (0.2, not
//! 0.20000000000000001), strings quoted, arrays and inline tables
//! recursively.
std::string valueText( const toml::node& node )
{
    if ( const auto* real = node.as_floating_point() )
    {
        char buffer[64];
        const auto end =
            std::to_chars( buffer, buffer + sizeof( buffer ), real->get() ).ptr;
        std::string text( buffer, end );
        // Keep floats recognisable as such: 1 -> 1.0.
        if ( text.find_first_of( ".eEn" ) == std::string::npos )
            text += ".0";
        return text;
    }
    if ( const auto* array = node.as_array() )
    {
        std::string text = "[";
        for ( std::size_t k = 0; k < array->size(); ++k )
            text += ( k ? ", " : "" ) + valueText( *array->get( k ) );
        return text + "]";
    }
    if ( const auto* table = node.as_table() )
    {
        std::string text = "{";
        bool first = true;
        for ( auto&& [key, value] : *table )
        {
            text += ( first ? " " : ", " ) + std::string( key.str() ) + " = " +
                    valueText( value );
            first = false;
        }
        return text + " }";
    }
    std::ostringstream text;
    node.visit( [&]( auto&& leaf ) { text << leaf; } );
    return text.str();
}

//! Appends "path = value" for every leaf under `node`.
void flatten( const toml::node& node, const std::string& path,
              std::vector<std::string>& lines )
{
    if ( const auto* table = node.as_table() )
    {
        for ( auto&& [key, value] : *table )
            flatten( value,
                     path.empty() ? std::string( key.str() )
                                  : path + "." + std::string( key.str() ),
                     lines );
        return;
    }
    const auto* array = node.as_array();
    if ( array && !array->empty() && array->is_array_of_tables() )
    {
        for ( std::size_t k = 0; k < array->size(); ++k )
            flatten( *array->get( k ), path + "[" + std::to_string( k ) + "]",
                     lines );
        return;
    }
    if ( ignoredKey( path ) )
        return;
    lines.push_back( path + " = " + valueText( node ) );
}

//! "path = value" lines as a map path -> value.
std::map<std::string, std::string> keyValues( const std::string& fingerprint )
{
    std::map<std::string, std::string> values;
    std::istringstream in( fingerprint );
    for ( std::string line; std::getline( in, line ); )
    {
        const auto at = line.find( " = " );
        if ( at != std::string::npos )
            values[line.substr( 0, at )] = line.substr( at + 3 );
    }
    return values;
}

} // namespace

//---------------------------------------------------------------------------//
std::string caseFingerprint( const toml::table& root )
{
    std::vector<std::string> lines;
    flatten( root, "", lines );
    std::sort( lines.begin(), lines.end() );
    std::string text;
    for ( const std::string& line : lines )
        text += line + "\n";
    return text;
}

std::uint64_t fnv1aHash( const std::string& text )
{
    std::uint64_t hash = 14695981039346656037ull;
    for ( const unsigned char c : text )
    {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return hash;
}

std::string hashText( const std::uint64_t hash )
{
    char buffer[17];
    std::snprintf( buffer, sizeof( buffer ), "%016llx",
                   static_cast<unsigned long long>( hash ) );
    return buffer;
}

std::string fingerprintDifferences( const std::string& checkpoint,
                                    const std::string& now,
                                    const std::size_t max_lines )
{
    const auto before = keyValues( checkpoint );
    const auto after = keyValues( now );
    std::vector<std::string> lines;
    for ( const auto& [key, value] : before )
    {
        const auto it = after.find( key );
        if ( it == after.end() )
            lines.push_back( "  " + key + ": " + value +
                             " in the checkpoint, not set now" );
        else if ( it->second != value )
            lines.push_back( "  " + key + ": " + value +
                             " in the checkpoint, " + it->second + " now" );
    }
    for ( const auto& [key, value] : after )
        if ( !before.count( key ) )
            lines.push_back( "  " + key + ": not set in the checkpoint, " +
                             value + " now" );
    std::sort( lines.begin(), lines.end() );
    std::string text;
    for ( std::size_t k = 0; k < lines.size() && k < max_lines; ++k )
        text += lines[k] + "\n";
    if ( lines.size() > max_lines )
        text += "  ... and " + std::to_string( lines.size() - max_lines ) +
                " more\n";
    return text;
}

} // namespace mpm
