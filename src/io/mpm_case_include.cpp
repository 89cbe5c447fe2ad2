#include <io/mpm_case_include.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//! Included files may include others up to this depth.
constexpr int max_include_depth = 8;

//! Directory part of a path, with a trailing '/', or "" for a bare name.
std::string directoryOf( const std::string& path )
{
    const auto slash = path.find_last_of( '/' );
    return slash == std::string::npos ? "" : path.substr( 0, slash + 1 );
}

//! Lay `top` over `base` (see resolveIncludes), moving nodes out of top.
void overlay( toml::table& base, toml::table& top )
{
    for ( auto&& [key, top_node] : top )
    {
        toml::node* base_node = base.get( key.str() );
        if ( base_node && base_node->is_table() && top_node.is_table() )
        {
            overlay( *base_node->as_table(), *top_node.as_table() );
            continue;
        }
        if ( base_node && base_node->is_array_of_tables() &&
             top_node.is_array_of_tables() )
        {
            toml::array& base_array = *base_node->as_array();
            toml::array& top_array = *top_node.as_array();
            for ( std::size_t i = 0; i < top_array.size(); ++i )
            {
                if ( i < base_array.size() )
                    overlay( *base_array[i].as_table(),
                             *top_array[i].as_table() );
                else
                    base_array.push_back(
                        std::move( *top_array[i].as_table() ) );
            }
            continue;
        }
        base.insert_or_assign( key, std::move( top_node ) );
    }
}

//! The file names listed by an `include` node, reporting a wrong type.
std::vector<std::pair<std::string, const toml::node*>>
includeList( const toml::node& node, Diagnostics& diag )
{
    const std::string expected =
        "a file name or an array of file names (paths relative to the "
        "including case file)";
    std::vector<std::pair<std::string, const toml::node*>> files;
    if ( const auto* single = node.as_string() )
        files.emplace_back( single->get(), &node );
    else if ( const auto* a = node.as_array() )
    {
        for ( const toml::node& element : *a )
        {
            if ( const auto* s = element.as_string() )
                files.emplace_back( s->get(), &element );
            else
                diag.mismatch( element, "include", expected );
        }
    }
    else
        diag.mismatch( node, "include", expected );
    return files;
}

void resolve( toml::table& root, const std::string& file_name,
              Diagnostics& diag, std::vector<std::string>& chain )
{
    const toml::node* include = root.get( "include" );
    if ( !include )
        return;
    toml::table merged;
    for ( const auto& [name, where] : includeList( *include, diag ) )
    {
        const std::string path = !name.empty() && name[0] == '/'
                                     ? name
                                     : directoryOf( file_name ) + name;
        bool circular = false;
        for ( const std::string& open : chain )
            circular = circular || open == path;
        if ( circular || chain.size() >= max_include_depth )
        {
            diag.keyError( *where, "include",
                           circular ? "'" + path +
                                          "' includes itself (directly or "
                                          "through other files)"
                                    : "includes nested deeper than " +
                                          std::to_string( max_include_depth ) +
                                          " files" );
            continue;
        }
        std::ifstream in( path, std::ios::binary );
        if ( !in )
        {
            diag.keyError( *where, "include",
                           "cannot open the included file '" + path + "' (" +
                               std::strerror( errno ) + ")" );
            continue;
        }
        std::ostringstream text;
        text << in.rdbuf();
        toml::table included;
        try
        {
            included = toml::parse( text.str(), path );
        }
        catch ( const toml::parse_error& e )
        {
            diag.error( e.source(),
                        "invalid TOML: " + std::string( e.description() ) );
            continue;
        }
        chain.push_back( path );
        resolve( included, path, diag, chain );
        chain.pop_back();
        overlay( merged, included );
    }
    root.erase( "include" );
    overlay( merged, root );
    // Move the merged keys back so root keeps its own source position.
    root.clear();
    for ( auto&& [key, node] : merged )
        root.insert( key, std::move( node ) );
}

} // namespace

//---------------------------------------------------------------------------//
void resolveIncludes( toml::table& root, const std::string& file_name,
                      Diagnostics& diag )
{
    std::vector<std::string> chain{ file_name };
    resolve( root, file_name, diag, chain );
}

} // namespace Impl
} // namespace mpm
