#include <io/mpm_case_file.hpp>
#include <io/mpm_case_include.hpp>
#include <io/mpm_case_limits.hpp>
#include <io/mpm_toml_prescan.hpp>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//! What the includes of one case have used of the limits.
struct IncludeBudget
{
    int files = 0;
    std::size_t bytes = 0;
    bool exhausted = false; //!< a limit was reported; stop including
};

//! The canonical form of a path ("./a.toml" and "a.toml" are one file).
std::string canonicalPath( const std::string& path )
{
    std::error_code error;
    const auto canonical = std::filesystem::weakly_canonical( path, error );
    return error ? path : canonical.string();
}

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

//! Why the file at path cannot be included now, or "".
std::string includeRefusal( const std::string& canonical,
                            const std::vector<std::string>& chain,
                            const IncludeBudget& budget )
{
    for ( const std::string& open : chain )
        if ( open == canonical )
            return "'" + canonical +
                   "' includes itself (directly or through other files)";
    if ( chain.size() >= static_cast<std::size_t>( max_include_depth ) )
        return "includes nested deeper than " +
               std::to_string( max_include_depth ) + " files";
    if ( budget.files >= max_include_files )
        return "expected at most " + std::to_string( max_include_files ) +
               " included files in all (repeats counted), found more; "
               "include each shared file once";
    return "";
}

void resolve( toml::table& root, const std::string& file_name,
              Diagnostics& diag, std::vector<std::string>& chain,
              IncludeBudget& budget )
{
    const toml::node* include = root.get( "include" );
    if ( !include )
        return;
    toml::table merged;
    for ( const auto& [name, where] : includeList( *include, diag ) )
    {
        if ( budget.exhausted )
            break;
        const std::string path = !name.empty() && name[0] == '/'
                                     ? name
                                     : directoryOf( file_name ) + name;
        const std::string canonical = canonicalPath( path );
        const std::string refusal = includeRefusal( canonical, chain, budget );
        if ( !refusal.empty() )
        {
            diag.keyError( *where, "include", refusal );
            budget.exhausted = budget.files >= max_include_files;
            continue;
        }
        ++budget.files;
        std::string text;
        try
        {
            // The per-file limit, or what is left of the case's total.
            const std::size_t left = max_case_total_bytes - budget.bytes;
            text =
                readRegularFile( path, std::min( left, max_case_file_bytes ) );
        }
        catch ( const CaseFileError& e )
        {
            diag.keyError( *where, "include",
                           "cannot include '" + path + "': " + e.what() );
            continue;
        }
        budget.bytes += text.size();
        if ( !prescanToml( text, path, diag ) )
            continue;
        toml::table included;
        try
        {
            included = toml::parse( text, path );
        }
        catch ( const toml::parse_error& e )
        {
            diag.error( e.source(),
                        "invalid TOML: " + std::string( e.description() ) );
            continue;
        }
        chain.push_back( canonical );
        resolve( included, path, diag, chain, budget );
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
                      Diagnostics& diag, const std::size_t bytes_read )
{
    std::vector<std::string> chain{ canonicalPath( file_name ) };
    IncludeBudget budget;
    budget.bytes = std::min( bytes_read, max_case_total_bytes );
    resolve( root, file_name, diag, chain, budget );
}

} // namespace Impl
} // namespace mpm
