// The declared case keys (src/io/mpm_case_schema.hpp, mpm_case_keys.hpp)
// against their documentation: docs/case-file.md lists every key of every
// table in that table's section, and no other key; for [solver] and [water]
// with the type, default and range the reader uses.
#include <case/mpm_case_config.hpp>
#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_schema.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef RAINSLIDE_DOCS_DIR
#define RAINSLIDE_DOCS_DIR "/work/main/docs"
#endif

namespace
{
//! A documented key: its type, default and allowed columns.
struct DocumentedKey
{
    std::string type, default_value, allowed;
};

//! The rows `| `key` | type | unit | default | allowed |` of the table
//! below the heading that starts with `heading` in docs/case-file.md.
std::map<std::string, DocumentedKey>
documentedKeys( const std::string& heading )
{
    std::ifstream in( RAINSLIDE_DOCS_DIR "/case-file.md" );
    EXPECT_TRUE( in.good() ) << "cannot read docs/case-file.md";
    std::map<std::string, DocumentedKey> keys;
    std::string line;
    bool in_section = false, in_table = false;
    while ( std::getline( in, line ) )
    {
        if ( line.rfind( "## ", 0 ) == 0 || line.rfind( "### ", 0 ) == 0 )
        {
            if ( in_section )
                break;
            in_section = line.rfind( heading, 0 ) == 0;
            continue;
        }
        if ( !in_section )
            continue;
        const bool row = line.rfind( "| `", 0 ) == 0;
        if ( in_table && !row && line.rfind( "|", 0 ) != 0 )
            break; // the table ended
        if ( !row )
            continue;
        in_table = true;
        std::vector<std::string> cells;
        std::stringstream split( line.substr( 1 ) );
        for ( std::string cell; std::getline( split, cell, '|' ); )
        {
            const auto first = cell.find_first_not_of( ' ' );
            const auto last = cell.find_last_not_of( ' ' );
            cells.push_back( first == std::string::npos
                                 ? ""
                                 : cell.substr( first, last - first + 1 ) );
        }
        if ( cells.size() < 5 )
            continue;
        const std::string name = cells[0].substr( 1, cells[0].size() - 2 );
        keys[name] = { cells[1], cells[3], cells[4] };
    }
    return keys;
}

//! The documented range in the reader's notation ("in (0, 1]", ">= 0").
std::string normalisedRange( std::string text )
{
    for ( std::string::size_type at;
          ( at = text.find( "≥" ) ) != std::string::npos; )
        text.replace( at, std::string( "≥" ).size(), ">=" );
    if ( !text.empty() && ( text[0] == '(' || text[0] == '[' ) )
        text = "in " + text;
    return text;
}

template <class Config>
void expectDocumented( const std::vector<mpm::Impl::ConfigKey<Config>>& keys,
                       const std::string& heading )
{
    const auto documented = documentedKeys( heading );
    ASSERT_FALSE( documented.empty() ) << heading;
    static const Config defaults;
    for ( const auto& key : keys )
    {
        SCOPED_TRACE( key.name );
        const auto found = documented.find( key.name );
        ASSERT_NE( found, documented.end() ) << "not documented";
        const DocumentedKey& doc = found->second;
        if ( key.number )
        {
            EXPECT_EQ( doc.type, "number" );
            EXPECT_EQ( std::stod( doc.default_value ), defaults.*key.number );
            const std::string range = key.range.text();
            EXPECT_EQ( normalisedRange( doc.allowed ).rfind( range, 0 ), 0u )
                << "documented '" << doc.allowed << "', read as '" << range
                << "'";
        }
        else if ( key.choices )
        {
            EXPECT_EQ( doc.type, "string" );
            EXPECT_EQ( doc.default_value,
                       "\"" + ( *key.choices )[key.get_choice( defaults )] +
                           "\"" );
        }
        else
        {
            EXPECT_EQ( doc.type, "boolean" );
            EXPECT_EQ( doc.default_value,
                       defaults.*key.flag ? "true" : "false" );
        }
    }
    for ( const auto& [name, doc] : documented )
    {
        bool declared = false;
        for ( const auto& key : keys )
            declared = declared || name == key.name;
        EXPECT_TRUE( declared ) << "documented but not read: " << name;
    }
}

TEST( CaseSchema, solver_keys_are_documented )
{
    expectDocumented( mpm::Impl::solverKeys(), "## `[solver]`" );
}

TEST( CaseSchema, water_keys_are_documented )
{
    expectDocumented( mpm::Impl::waterKeys(), "## `[water]`" );
}

// Every table's section (## or ### `table`) lists exactly the keys the
// reader accepts.
TEST( CaseSchema, every_table_is_documented )
{
    for ( const auto& [table, keys] : mpm::Impl::caseTableKeys() )
    {
        SCOPED_TRACE( table );
        auto documented = documentedKeys( "## `" + table + "`" );
        if ( documented.empty() )
            documented = documentedKeys( "### `" + table + "`" );
        ASSERT_FALSE( documented.empty() ) << "no section with a key table";
        for ( const std::string& key : keys )
            EXPECT_EQ( documented.count( key ), 1u )
                << "not documented: " << key;
        for ( const auto& entry : documented )
            EXPECT_NE( std::find( keys.begin(), keys.end(), entry.first ),
                       keys.end() )
                << "documented but not read: " << entry.first;
    }
    EXPECT_THROW( mpm::Impl::keysOf( "[nothing]" ), std::logic_error );
}

} // namespace
