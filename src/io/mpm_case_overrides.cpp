#include <io/mpm_case_limits.hpp>
#include <io/mpm_case_overrides.hpp>
#include <io/mpm_toml_prescan.hpp>

#include <memory>
#include <optional>

namespace mpm
{
namespace Impl
{
namespace
{
//! One component of an override's key: a name and an optional [index].
struct KeyPart
{
    std::string name;
    std::optional<std::size_t> index;
};

//! The parts of "a.b[2].c"; empty on a malformed key (message in `why`).
std::vector<KeyPart> splitKey( const std::string& key, std::string& why )
{
    std::vector<KeyPart> parts;
    std::size_t at = 0;
    while ( true )
    {
        KeyPart part;
        while ( at < key.size() && isBareKeyCharacter( key[at] ) )
            part.name += key[at++];
        if ( part.name.empty() || part.name.size() > max_name_length )
        {
            why = "expected a key name of 1 to " +
                  std::to_string( max_name_length ) +
                  " letters, digits, '_' or '-' at character " +
                  std::to_string( at + 1 );
            return {};
        }
        if ( at < key.size() && key[at] == '[' )
        {
            const std::size_t close = key.find( ']', at );
            const std::string digits =
                close == std::string::npos
                    ? std::string()
                    : key.substr( at + 1, close - at - 1 );
            if ( digits.empty() || digits.size() > 6 ||
                 digits.find_first_not_of( "0123456789" ) != std::string::npos )
            {
                why = "expected an array index [0], [1], ... after '" +
                      part.name + "'";
                return {};
            }
            part.index = std::stoul( digits );
            at = close + 1;
        }
        parts.push_back( part );
        if ( at == key.size() )
            return parts;
        if ( key[at] != '.' )
        {
            why = "unexpected '" + std::string( 1, key[at] ) +
                  "' at character " + std::to_string( at + 1 );
            return {};
        }
        ++at;
    }
}

//! Kind of a node for messages.
std::string kindOf( const toml::node& node )
{
    if ( node.is_table() )
        return "a table";
    if ( node.is_array() )
        return "an array";
    return "a value";
}

//! The "source" of an override in messages: "--set KEY=VALUE:1:1".
toml::source_region overrideSource( const std::string& label )
{
    toml::source_region where;
    where.path = std::make_shared<const std::string>( label );
    where.begin = { 1, 1 };
    where.end = { 1, 1 };
    return where;
}

/*!
  Applies one override; returns an empty string or what is wrong with it.
  `label` ("--set KEY=VALUE") is the source path of the new value.
*/
std::string applyOne( toml::table& root, const std::string& text,
                      const std::string& label )
{
    const std::size_t equals = text.find( '=' );
    if ( equals == std::string::npos )
        return "expected KEY=VALUE, e.g. solver.courant_number=0.5";
    std::string why;
    const auto parts = splitKey( text.substr( 0, equals ), why );
    if ( parts.empty() )
        return "key '" + text.substr( 0, equals ) + "': " + why;
    if ( parts.front().name == "include" )
        return "key 'include': includes are resolved before the overrides "
               "and cannot be set";
    // What toml++ does not survive (deep nesting, bytes outside ASCII) is
    // refused before it parses, as in a case file.
    const std::string snippet = "value = " + text.substr( equals + 1 );
    Diagnostics prescan( label );
    if ( !prescanToml( snippet, label, prescan ) )
        return "value '" + text.substr( equals + 1 ) + "': " + prescan.report();
    toml::table value_table;
    try
    {
        value_table = toml::parse( snippet, std::string_view( label ) );
    }
    catch ( const toml::parse_error& e )
    {
        return "value '" + text.substr( equals + 1 ) + "': not a TOML value (" +
               std::string( e.description() ) +
               "); strings need quotes: name=\"text\"";
    }
    toml::node* value = value_table.get( "value" );
    if ( !value || value_table.size() != 1 )
        return "value '" + text.substr( equals + 1 ) +
               "': expected one TOML value";

    toml::table* table = &root;
    std::string path;
    for ( std::size_t k = 0; k < parts.size(); ++k )
    {
        const KeyPart& part = parts[k];
        const bool last = k + 1 == parts.size();
        path += ( path.empty() ? "" : "." ) + part.name;
        toml::node* node = table->get( part.name );
        if ( part.index )
        {
            toml::array* array = node ? node->as_array() : nullptr;
            if ( !array )
                return "key '" + path + "': expected an array, found " +
                       ( node ? kindOf( *node ) : "nothing" );
            if ( *part.index >= array->size() )
                return "key '" + path + "': index " +
                       std::to_string( *part.index ) + " is past its " +
                       std::to_string( array->size() ) + " element(s)";
            path += "[" + std::to_string( *part.index ) + "]";
            if ( last )
            {
                const auto at = array->cbegin() +
                                static_cast<std::ptrdiff_t>( *part.index );
                value->visit( [&]( auto&& v )
                              { array->replace( at, std::move( v ) ); } );
                return "";
            }
            node = array->get( *part.index );
        }
        else if ( last )
        {
            // The key carries the override's name into the reader's
            // messages (an unknown key).
            value->visit(
                [&]( auto&& v )
                {
                    table->insert_or_assign(
                        toml::key( part.name, overrideSource( label ) ),
                        std::move( v ) );
                } );
            return "";
        }
        else if ( !node )
            node =
                table
                    ->insert( toml::key( part.name, overrideSource( label ) ),
                              toml::table{} )
                    .first->second.as_table();
        table = node ? node->as_table() : nullptr;
        if ( !table )
            return "key '" + path + "': expected a table, found " +
                   kindOf( *node );
    }
    return "";
}

} // namespace

//---------------------------------------------------------------------------//
void applyOverrides( toml::table& root,
                     const std::vector<std::string>& overrides,
                     Diagnostics& diag )
{
    if ( overrides.size() > max_overrides )
    {
        diag.error( overrideSource( "--set" ),
                    "at most " + std::to_string( max_overrides ) +
                        " overrides, found " +
                        std::to_string( overrides.size() ) );
        return;
    }
    for ( const std::string& text : overrides )
    {
        const std::string label = "--set " + text;
        if ( text.size() > max_text_length )
        {
            diag.error(
                overrideSource( "--set" ),
                "an override has at most " + std::to_string( max_text_length ) +
                    " characters, found " + std::to_string( text.size() ) );
            continue;
        }
        const std::string problem = applyOne( root, text, label );
        if ( !problem.empty() )
            diag.error( overrideSource( label ), problem );
    }
}

} // namespace Impl
} // namespace mpm
