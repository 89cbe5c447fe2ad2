#ifndef MPM_TOML_ACCESS_HPP
#define MPM_TOML_ACCESS_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_diagnostics.hpp>
#include <io/mpm_case_limits.hpp>

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Typed access to a parsed TOML case file: every getter reports a wrong
// type, a value out of range or a missing required key to Diagnostics.
// Internal to src/io/mpm_case_*.
//---------------------------------------------------------------------------//

//---------------------------------------------------------------------------//
//! \brief A finite number (integers accepted) in range, or an error.
inline std::optional<double>
readNumber( const toml::node& node, const std::string& path, const Range& range,
            const std::string& unit, Diagnostics& diag )
{
    std::optional<double> value;
    if ( auto i = node.as_integer() )
        value = static_cast<double>( i->get() );
    else if ( auto f = node.as_floating_point() )
        value = f->get();
    if ( !value || !std::isfinite( *value ) || !range.contains( *value ) )
    {
        diag.mismatch( node, path, numberExpectation( range, unit ) );
        return std::nullopt;
    }
    return value;
}

//---------------------------------------------------------------------------//
//! \brief A point [x, y] of two finite numbers, or an error.
inline std::optional<Point2> readPoint( const toml::node& node,
                                        const std::string& path,
                                        const std::string& unit,
                                        Diagnostics& diag )
{
    const auto* arr = node.as_array();
    if ( !arr || arr->size() != 2 )
    {
        diag.mismatch( node, path, "a point [x, y] in " + unit );
        return std::nullopt;
    }
    const auto x =
        readNumber( *arr->get( 0 ), path + "[0]", Range::any(), unit, diag );
    const auto y =
        readNumber( *arr->get( 1 ), path + "[1]", Range::any(), unit, diag );
    if ( !x || !y )
        return std::nullopt;
    return Point2{ *x, *y };
}

//---------------------------------------------------------------------------//
//! Whether a key must be present.
enum class Need
{
    Required,
    Optional
};

//---------------------------------------------------------------------------//
//! One TOML table with its dotted path: typed getters that report errors.
class TableReader
{
  public:
    TableReader( const toml::table& table, std::string path, Diagnostics& diag )
        : _table( table )
        , _path( std::move( path ) )
        , _diag( diag )
    {
    }

    const toml::table& table() const { return _table; }
    const std::string& path() const { return _path; }
    Diagnostics& diag() const { return _diag; }
    std::string keyPath( const std::string& key ) const
    {
        return joinPath( _path, key );
    }
    const toml::node* find( const std::string& key ) const
    {
        return _table.get( key );
    }

    /*!
      \brief Report every key not in known (suggesting the closest), except
      those in checked_elsewhere. where names the table in the message.
    */
    void checkKeys( const std::vector<std::string>& known,
                    const std::string& where,
                    const std::vector<std::string>& checked_elsewhere = {} )
    {
        for ( auto&& [key, node] : _table )
        {
            const std::string name( key.str() );
            if ( std::count( known.begin(), known.end(), name ) ||
                 std::count( checked_elsewhere.begin(), checked_elsewhere.end(),
                             name ) )
                continue;
            const std::string guess = closestWord( name, known );
            std::string text =
                "key '" + shortText( keyPath( name ) ) + "': unknown key";
            if ( !guess.empty() && _table.get( guess ) == nullptr )
            {
                text += "; did you mean '" + guess + "'?";
                _suggested.insert( guess );
            }
            else
                text += "; the keys allowed in " + where + " are " +
                        quotedList( known );
            _diag.error( key.source(), text );
        }
    }

    //! \brief Report a missing required key (unless a typo of it was found).
    void missing( const std::string& key, const std::string& expected )
    {
        if ( _suggested.count( key ) )
            return;
        _diag.error( _table.source(),
                     "key '" + keyPath( key ) +
                         "': required key is missing; expected " + expected );
    }

    //! \brief The node of key, or null (reporting it if required).
    const toml::node* node( const std::string& key, const Need need,
                            const std::string& expected )
    {
        const toml::node* n = _table.get( key );
        if ( !n && need == Need::Required )
            missing( key, expected );
        return n;
    }

    std::optional<double> number( const std::string& key, const Range& range,
                                  const std::string& unit, const Need need )
    {
        const auto* n = node( key, need, numberExpectation( range, unit ) );
        return n ? readNumber( *n, keyPath( key ), range, unit, _diag )
                 : std::nullopt;
    }

    std::optional<int> integer( const std::string& key, const int lo,
                                const int hi, const Need need )
    {
        const std::string expected =
            "an integer " + ( hi == std::numeric_limits<int>::max()
                                  ? ">= " + std::to_string( lo )
                                  : "in " + std::to_string( lo ) + ".." +
                                        std::to_string( hi ) );
        const auto* n = node( key, need, expected );
        if ( !n )
            return std::nullopt;
        const auto* i = n->as_integer();
        if ( !i || i->get() < lo || i->get() > hi )
        {
            _diag.mismatch( *n, keyPath( key ), expected );
            return std::nullopt;
        }
        return static_cast<int>( i->get() );
    }

    std::optional<bool> boolean( const std::string& key, const Need need )
    {
        const auto* n = node( key, need, "true or false" );
        if ( !n )
            return std::nullopt;
        if ( !n->is_boolean() )
        {
            _diag.mismatch( *n, keyPath( key ), "true or false" );
            return std::nullopt;
        }
        return n->as_boolean()->get();
    }

    /*!
      \brief A name (non-empty, at most max_name_length characters, no
      control characters) or, with allow_text, any text of at most
      max_text_length characters without NUL.
    */
    std::optional<std::string> string( const std::string& key, const Need need,
                                       const bool allow_text = false )
    {
        const std::size_t max_length =
            allow_text ? max_text_length : max_name_length;
        const std::string expected =
            allow_text ? "a string of at most " + std::to_string( max_length ) +
                             " characters without NUL"
                       : "a non-empty name of at most " +
                             std::to_string( max_length ) +
                             " characters without control characters";
        const auto* n = node( key, need, "a string" );
        if ( !n )
            return std::nullopt;
        const auto* s = n->as_string();
        auto bad = [allow_text]( const char c )
        {
            const auto u = static_cast<unsigned char>( c );
            return allow_text ? u == 0 : u < 0x20 || u == 0x7f;
        };
        if ( !s || ( !allow_text && s->get().empty() ) ||
             s->get().size() > max_length ||
             std::any_of( s->get().begin(), s->get().end(), bad ) )
        {
            _diag.mismatch( *n, keyPath( key ), expected );
            return std::nullopt;
        }
        return s->get();
    }

    //! \brief Index of the value of key in options, or an error.
    std::optional<int> choice( const std::string& key,
                               const std::vector<std::string>& options,
                               const Need need )
    {
        const std::string expected = "one of " + quotedList( options, '"' );
        const auto* n = node( key, need, expected );
        if ( !n )
            return std::nullopt;
        if ( const auto* s = n->as_string() )
        {
            const auto it =
                std::find( options.begin(), options.end(), s->get() );
            if ( it != options.end() )
                return static_cast<int>( it - options.begin() );
            const std::string guess = closestWord( s->get(), options );
            if ( !guess.empty() )
            {
                _diag.keyError( *n, keyPath( key ),
                                "expected " + expected + ", found \"" +
                                    s->get() + "\"; did you mean \"" + guess +
                                    "\"?" );
                return std::nullopt;
            }
        }
        _diag.mismatch( *n, keyPath( key ), expected );
        return std::nullopt;
    }

    std::optional<Point2> point( const std::string& key,
                                 const std::string& unit, const Need need )
    {
        const auto* n = node( key, need, "a point [x, y] in " + unit );
        return n ? readPoint( *n, keyPath( key ), unit, _diag ) : std::nullopt;
    }

    //! \brief A list of points [[x, y], ...]; min_count to max_count.
    std::optional<std::vector<Point2>>
    points( const std::string& key, const std::size_t min_count,
            const std::string& unit, const Need need,
            const std::size_t max_count = max_list_points )
    {
        const std::string expected =
            "an array of " + std::to_string( min_count ) + " to " +
            std::to_string( max_count ) + " points [[x, y], ...] in " + unit;
        const auto* n = node( key, need, expected );
        if ( !n )
            return std::nullopt;
        const auto* arr = n->as_array();
        if ( !arr || arr->size() < min_count || arr->size() > max_count )
        {
            _diag.mismatch( *n, keyPath( key ), expected );
            return std::nullopt;
        }
        std::vector<Point2> result;
        bool ok = true;
        for ( std::size_t k = 0; k < arr->size(); ++k )
        {
            const auto p = readPoint(
                *arr->get( k ),
                keyPath( key ) + "[" + std::to_string( k ) + "]", unit, _diag );
            ok = ok && p.has_value();
            if ( p )
                result.push_back( *p );
        }
        return ok ? std::optional<std::vector<Point2>>( result ) : std::nullopt;
    }

    //! \brief A sub-table, or null (reporting a wrong type or absence).
    const toml::table* subTable( const std::string& key, const Need need )
    {
        const auto* n = node( key, need, "a table [" + keyPath( key ) + "]" );
        if ( n && !n->is_table() )
        {
            _diag.mismatch( *n, keyPath( key ),
                            "a table [" + keyPath( key ) + "]" );
            return nullptr;
        }
        return n ? n->as_table() : nullptr;
    }

    //! \brief An array of tables [[key]], or null (reporting errors).
    const toml::array* tableArray( const std::string& key, const Need need,
                                   const std::string& header )
    {
        std::string expected = "an array of tables " + header;
        const auto* n = node( key, need, expected );
        if ( !n )
            return nullptr;
        if ( n->is_table() )
            expected += " (write " + header + ", not " +
                        header.substr( 1, header.size() - 2 ) + ")";
        const auto* arr = n->as_array();
        if ( !arr || !std::all_of( arr->begin(), arr->end(),
                                   []( const toml::node& e )
                                   { return e.is_table(); } ) )
        {
            _diag.mismatch( *n, keyPath( key ), expected );
            return nullptr;
        }
        return arr;
    }

  private:
    const toml::table& _table;
    std::string _path;
    Diagnostics& _diag;
    std::set<std::string> _suggested;
};

//---------------------------------------------------------------------------//
//! The path of element k of the array at `path`: path[k].
inline std::string indexed( const std::string& path, const std::size_t k )
{
    return path + "[" + std::to_string( k ) + "]";
}

/*!
  \brief Calls read(r) with the TableReader r of every table of an array of
  tables (path prefix[k]), after checking its keys against `known` (`where`
  names the table in the messages).
*/
template <class Read>
void forEachTable( const toml::array& array, const std::string& prefix,
                   Diagnostics& diag, const std::vector<std::string>& known,
                   const std::string& where, Read&& read )
{
    for ( std::size_t k = 0; k < array.size(); ++k )
    {
        TableReader r( *array.get( k )->as_table(), indexed( prefix, k ),
                       diag );
        r.checkKeys( known, where );
        read( r );
    }
}

//! Reports a `name` key of r used before (first_path: name -> the path of
//! the table that used it first) and records it otherwise; `what` names
//! the name ("material name") and `hint` ends the message.
inline void checkUniqueName( TableReader& r, const std::string& name,
                             std::map<std::string, std::string>& first_path,
                             const std::string& what, const std::string& hint )
{
    const auto [first, inserted] = first_path.emplace( name, r.path() );
    if ( !inserted )
        r.diag().keyError( *r.find( "name" ), r.keyPath( "name" ),
                           "duplicate " + what + " '" + name +
                               "' (already used by " + first->second + ")" +
                               hint );
}

} // namespace Impl
} // namespace mpm

#endif // MPM_TOML_ACCESS_HPP
