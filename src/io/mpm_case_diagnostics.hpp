#ifndef MPM_CASE_DIAGNOSTICS_HPP
#define MPM_CASE_DIAGNOSTICS_HPP

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Error messages of the case reader: value formatting, key suggestions,
// allowed ranges and the error collector. Internal to src/io/mpm_case_*.
//---------------------------------------------------------------------------//

//! \brief Shortest decimal text that reads back as v ("0.7", "1e7").
inline std::string formatNumber( const double v )
{
    if ( std::isnan( v ) )
        return "nan";
    if ( std::isinf( v ) )
        return v > 0 ? "inf" : "-inf";
    // Fewest significant digits that read back exactly.
    char buf[40];
    int precision = 1;
    for ( ; precision < 17; ++precision )
    {
        std::snprintf( buf, sizeof buf, "%.*g", precision, v );
        if ( std::strtod( buf, nullptr ) == v )
            break;
    }
    std::snprintf( buf, sizeof buf, "%.*g", precision, v );
    const std::string text( buf );
    const auto e = text.find( 'e' );
    if ( e == std::string::npos )
        return text;

    // Plain notation up to 1e6 (20, 250000); exponents as TOML users write
    // them above (1e7, not 1e+07) and below 1e-4 (1e-5).
    const int exponent = std::atoi( text.c_str() + e + 1 );
    if ( exponent >= 0 && exponent < 7 )
    {
        std::snprintf( buf, sizeof buf, "%.*f",
                       std::max( 0, precision - 1 - exponent ), v );
        return buf;
    }
    return text.substr( 0, e ) + "e" + std::to_string( exponent );
}

//---------------------------------------------------------------------------//
/*!
  \brief Text for a message: control characters as '?' and, beyond 60
  characters, the first 40 followed by "... (N characters)".
*/
inline std::string shortText( const std::string_view text )
{
    const std::size_t shown = text.size() > 60 ? 40 : text.size();
    std::string result( text.substr( 0, shown ) );
    for ( char& c : result )
        if ( static_cast<unsigned char>( c ) < 0x20 || c == 0x7f )
            c = '?';
    if ( shown < text.size() )
        result += "... (" + std::to_string( text.size() ) + " characters)";
    return result;
}

//---------------------------------------------------------------------------//
//! \brief What a TOML value is, for "found ..." in messages.
inline std::string describeNode( const toml::node& node )
{
    if ( auto v = node.as_integer() )
        return std::to_string( v->get() );
    if ( auto v = node.as_floating_point() )
    {
        std::string text = formatNumber( v->get() );
        if ( text.find_first_of( ".eni" ) == std::string::npos )
            text += ".0";
        return text;
    }
    if ( auto v = node.as_boolean() )
        return v->get() ? "true" : "false";
    if ( auto v = node.as_string() )
        return "string \"" + shortText( v->get() ) + "\"";
    if ( auto v = node.as_array() )
        return v->empty() ? std::string( "an empty array" )
                          : "an array of " + std::to_string( v->size() ) +
                                ( v->size() == 1 ? " element" : " elements" );
    if ( node.is_table() )
        return "a table";
    return "a date/time";
}

//---------------------------------------------------------------------------//
//! \brief Optimal string alignment distance (edits incl. transpositions).
inline int editDistance( const std::string_view a, const std::string_view b )
{
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d( n + 1, std::vector<int>( m + 1, 0 ) );
    for ( std::size_t i = 0; i <= n; ++i )
        d[i][0] = static_cast<int>( i );
    for ( std::size_t j = 0; j <= m; ++j )
        d[0][j] = static_cast<int>( j );
    for ( std::size_t i = 1; i <= n; ++i )
        for ( std::size_t j = 1; j <= m; ++j )
        {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min(
                { d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost } );
            if ( i > 1 && j > 1 && a[i - 1] == b[j - 2] &&
                 a[i - 2] == b[j - 1] )
                d[i][j] = std::min( d[i][j], d[i - 2][j - 2] + 1 );
        }
    return d[n][m];
}

//---------------------------------------------------------------------------//
/*!
  \brief The known word closest to word if it is a plausible typo (2 edits,
  3 for words of 10 or more characters), else "". Candidates whose length
  differs by more than that are skipped (the distance is at least the
  difference), so a long word costs nothing.
*/
inline std::string closestWord( const std::string& word,
                                const std::vector<std::string>& known )
{
    const std::size_t limit = word.size() >= 10 ? 3 : 2;
    std::string best;
    int best_distance = static_cast<int>( limit ) + 1;
    for ( const auto& candidate : known )
    {
        const std::size_t longer = std::max( word.size(), candidate.size() );
        const std::size_t shorter = std::min( word.size(), candidate.size() );
        if ( longer - shorter > limit )
            continue;
        const int distance = editDistance( word, candidate );
        if ( distance < best_distance )
        {
            best = candidate;
            best_distance = distance;
        }
    }
    return best;
}

//---------------------------------------------------------------------------//
//! \brief Words joined as "'a', 'b', 'c'" (quote = '\'') or with '"'.
inline std::string quotedList( const std::vector<std::string>& words,
                               const char quote = '\'' )
{
    std::string text;
    for ( const auto& w : words )
        text += ( text.empty() ? "" : ", " ) + ( quote + w + quote );
    return text;
}

//---------------------------------------------------------------------------//
//! \brief A character of a TOML bare key (letters, digits, '_', '-').
inline bool isBareKeyCharacter( const char c )
{
    return std::isalnum( static_cast<unsigned char>( c ) ) || c == '_' ||
           c == '-';
}

//---------------------------------------------------------------------------//
//! \brief Dotted key path: key appended to path, quoted if not a bare key.
inline std::string joinPath( const std::string& path, const std::string& key )
{
    const bool bare = !key.empty() &&
                      std::all_of( key.begin(), key.end(), isBareKeyCharacter );
    const std::string part = bare ? key : "\"" + key + "\"";
    return path.empty() ? part : path + "." + part;
}

//---------------------------------------------------------------------------//
//! An allowed interval of a number, with its text for messages.
struct Range
{
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;

    static Range any() { return {}; }
    static Range above( double v ) { return { v, hi_inf(), true, false }; }
    static Range atLeast( double v ) { return { v, hi_inf(), false, false }; }
    static Range atMost( double v ) { return { -hi_inf(), v, false, false }; }
    static Range interval( double l, bool l_open, double h, bool h_open )
    {
        return { l, h, l_open, h_open };
    }
    static double hi_inf() { return std::numeric_limits<double>::infinity(); }

    //! \brief Whether v is allowed (NaN never is).
    bool contains( const double v ) const
    {
        const bool lo_ok = lo_open ? v > lo : v >= lo;
        const bool hi_ok = hi_open ? v < hi : v <= hi;
        return lo_ok && hi_ok && !std::isnan( v );
    }

    //! \brief "in [0, 0.5)", "> 0", ">= 0", "<= 0" or "" for any number.
    std::string text() const
    {
        const bool has_lo = std::isfinite( lo ), has_hi = std::isfinite( hi );
        if ( has_lo && has_hi )
            return std::string( "in " ) + ( lo_open ? "(" : "[" ) +
                   formatNumber( lo ) + ", " + formatNumber( hi ) +
                   ( hi_open ? ")" : "]" );
        if ( has_lo )
            return ( lo_open ? "> " : ">= " ) + formatNumber( lo );
        if ( has_hi )
            return ( hi_open ? "< " : "<= " ) + formatNumber( hi );
        return "";
    }
};

//---------------------------------------------------------------------------//
//! \brief "a number in [0, 0.5)", "a number > 0 Pa", "a number in m".
inline std::string numberExpectation( const Range& range,
                                      const std::string& unit )
{
    std::string text = "a number";
    const std::string bounds = range.text();
    if ( !bounds.empty() )
        text += " " + bounds;
    if ( !unit.empty() )
        text += ( bounds.empty() ? " in " : " " ) + unit;
    return text;
}

//---------------------------------------------------------------------------//
//! Collects errors as "file:line:column: error: text".
class Diagnostics
{
  public:
    explicit Diagnostics( std::string file_name )
        : _file_name( std::move( file_name ) )
    {
    }

    //! \brief Record an error at a source region; its file is the region's
    //! (an included file) or, if unknown, the case file.
    void error( const toml::source_region& where, const std::string& text )
    {
        _entries.push_back( entry( where, "error", text ) );
    }

    //! \brief Record a warning "key 'path': text" at the position of a
    //! node (not an error: empty() and report() ignore it).
    void keyWarning( const toml::node& node, const std::string& path,
                     const std::string& text )
    {
        _warnings.push_back(
            entry( node.source(), "warning", "key '" + path + "': " + text ) );
    }

    //! \brief Record "key 'path': text" at the position of a node.
    void keyError( const toml::node& node, const std::string& path,
                   const std::string& text )
    {
        error( node.source(), "key '" + path + "': " + text );
    }

    //! \brief Record "key 'path': expected ..., found ..." for a node.
    void mismatch( const toml::node& node, const std::string& path,
                   const std::string& expected )
    {
        std::string found = describeNode( node );
        if ( auto s = node.as_string() )
        {
            char* end = nullptr;
            std::strtod( s->get().c_str(), &end );
            if ( !s->get().empty() && *end == '\0' &&
                 expected.rfind( "a number", 0 ) == 0 )
                found += " (a string: remove the quotes)";
        }
        keyError( node, path, "expected " + expected + ", found " + found );
    }

    bool empty() const { return _entries.empty(); }
    std::size_t count() const { return _entries.size(); }

    //! \brief All errors in file order (the case file first, then included
    //! files), one per line (at most 20 shown).
    std::string report() const
    {
        const auto sorted = inFileOrder( _entries );
        const std::size_t shown = std::min<std::size_t>( sorted.size(), 20 );
        std::string text;
        for ( std::size_t i = 0; i < shown; ++i )
            text += ( i ? "\n" : "" ) + sorted[i].text;
        if ( sorted.size() > shown )
            text += "\n(" + std::to_string( sorted.size() - shown ) +
                    " more errors not shown)";
        return text;
    }

    //! \brief The warnings in file order, one line each.
    std::vector<std::string> warnings() const
    {
        std::vector<std::string> lines;
        for ( const Entry& warning : inFileOrder( _warnings ) )
            lines.push_back( warning.text );
        return lines;
    }

  private:
    struct Entry
    {
        std::string file;
        int line;
        int column;
        std::string text;
    };

    //! "file:line:column: <kind>: text" at a source region (its file, or
    //! the case file if unknown).
    Entry entry( const toml::source_region& where, const std::string& kind,
                 const std::string& text ) const
    {
        const std::string file =
            where.path ? std::string( *where.path ) : _file_name;
        return { file, static_cast<int>( where.begin.line ),
                 static_cast<int>( where.begin.column ),
                 file + ":" + std::to_string( where.begin.line ) + ":" +
                     std::to_string( where.begin.column ) + ": " + kind + ": " +
                     text };
    }

    //! Entries sorted: the --set overrides first (an error there causes
    //! the errors it leads to elsewhere, e.g. an unknown material name),
    //! then the case file, then included files, each by line and column.
    std::vector<Entry> inFileOrder( std::vector<Entry> sorted ) const
    {
        std::stable_sort(
            sorted.begin(), sorted.end(),
            [this]( const Entry& a, const Entry& b )
            {
                const bool a_set = a.file.rfind( "--set ", 0 ) == 0;
                const bool b_set = b.file.rfind( "--set ", 0 ) == 0;
                if ( a_set != b_set )
                    return a_set;
                const bool a_main = a.file == _file_name;
                const bool b_main = b.file == _file_name;
                if ( a_main != b_main )
                    return a_main;
                if ( a.file != b.file )
                    return a.file < b.file;
                return a.line != b.line ? a.line < b.line : a.column < b.column;
            } );
        return sorted;
    }

    std::string _file_name;
    std::vector<Entry> _entries;
    std::vector<Entry> _warnings;
};

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_DIAGNOSTICS_HPP
