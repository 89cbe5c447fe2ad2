#include <io/mpm_case_limits.hpp>
#include <io/mpm_toml_prescan.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//! Lexical state of the scanner.
enum class Lex
{
    Plain,
    Comment,
    Basic,       // "..."
    Literal,     // '...'
    MultiBasic,  // """..."""
    MultiLiteral // '''...'''
};

//! A scanner over TOML text tracking line and column (1-based).
class Scanner
{
  public:
    Scanner( std::string_view text, const std::string& file_name,
             Diagnostics& diag )
        : _text( text )
        , _path( std::make_shared<const std::string>( file_name ) )
        , _diag( diag )
    {
    }

    bool run()
    {
        while ( _pos < _text.size() )
        {
            if ( !step() )
                return false;
        }
        return true;
    }

  private:
    bool startsWith( std::string_view s ) const
    {
        return _text.substr( _pos, s.size() ) == s;
    }

    void advance( std::size_t n = 1 )
    {
        for ( ; n > 0 && _pos < _text.size(); --n, ++_pos )
        {
            if ( _text[_pos] == '\n' )
            {
                ++_line;
                _column = 1;
                _line_blank = true;
            }
            else
            {
                ++_column;
                if ( _text[_pos] != ' ' && _text[_pos] != '\t' )
                    _line_blank = false;
            }
        }
    }

    bool fail( const std::string& text, const int column_offset = 0 )
    {
        toml::source_region where;
        where.begin = {
            static_cast<toml::source_index>( _line ),
            static_cast<toml::source_index>( _column + column_offset ) };
        where.end = where.begin;
        where.path = _path;
        _diag.error( where, text );
        return false;
    }

    //! One character (or string delimiter) of the text.
    bool step()
    {
        const char c = _text[_pos];
        switch ( _lex )
        {
        case Lex::Comment:
            if ( c == '\n' )
                _lex = Lex::Plain;
            break;
        case Lex::Basic:
            if ( c == '\\' )
                advance();
            else if ( c == '"' || c == '\n' )
                _lex = Lex::Plain;
            break;
        case Lex::Literal:
            if ( c == '\'' || c == '\n' )
                _lex = Lex::Plain;
            break;
        case Lex::MultiBasic:
            if ( c == '\\' )
                advance();
            else if ( startsWith( "\"\"\"" ) )
            {
                advance( 3 );
                _lex = Lex::Plain;
                return true;
            }
            break;
        case Lex::MultiLiteral:
            if ( startsWith( "'''" ) )
            {
                advance( 3 );
                _lex = Lex::Plain;
                return true;
            }
            break;
        case Lex::Plain:
            return plain( c );
        }
        advance();
        return true;
    }

    bool plain( const char c )
    {
        if ( static_cast<unsigned char>( c ) >= 0x80 )
            return fail( "invalid TOML: a character outside ASCII outside a "
                         "string or comment (only strings and comments may "
                         "hold other characters)" );
        switch ( c )
        {
        case '#':
            _lex = Lex::Comment;
            break;
        case '"':
            if ( startsWith( "\"\"\"" ) )
            {
                advance( 3 );
                _lex = Lex::MultiBasic;
                return true;
            }
            _lex = Lex::Basic;
            break;
        case '\'':
            if ( startsWith( "'''" ) )
            {
                advance( 3 );
                _lex = Lex::MultiLiteral;
                return true;
            }
            _lex = Lex::Literal;
            break;
        case '[':
            if ( _open.empty() && _line_blank )
            {
                if ( !tableHeaderStart() )
                    return false;
                _in_header = true;
            }
            _dots = 0;
            _open.push_back( { _in_header ? 'h' : c, _line, _column } );
            break;
        case '{':
            _dots = 0;
            _open.push_back( { c, _line, _column } );
            break;
        case '}':
            // toml++ 3.3 parses a '}' where an array expects a value as
            // the start of a value, breaking the precondition of its value
            // parser (an assertion in debug builds, undefined behaviour in
            // release ones): "e = [}". Never valid TOML.
            if ( !_open.empty() && _open.back().bracket == '[' )
                return fail( "invalid TOML: expected a value or ']' in the "
                             "array opened at line " +
                             std::to_string( _open.back().line ) + ", column " +
                             std::to_string( _open.back().column ) +
                             ", found '}'" );
            [[fallthrough]];
        case ']':
            _dots = 0;
            if ( !_open.empty() )
                _open.pop_back();
            _in_header = _in_header && !_open.empty();
            break;
        case '.':
            ++_dots;
            break;
        case '=':
        case ',':
        case '\n':
            _dots = 0;
            break;
        default:
            break;
        }
        if ( static_cast<int>( _open.size() ) + _dots > max_nesting_depth )
            return fail( "invalid case file: keys, arrays and inline tables "
                         "nested deeper than " +
                         std::to_string( max_nesting_depth ) +
                         " levels (dotted key parts, '[' and '{' counted)" );
        advance();
        return true;
    }

    /*!
      At the '[' of a table header ('[' or '[[' first on a line, outside
      any value): the name must start with a bare key character or a quote
      (or be ']' or the end: toml++ reports those). toml++ 3.3 calls its
      key parser on any other character, whose precondition it breaks:
      an assertion in debug builds, undefined behaviour in release ones
      ("[\n", "[[[a]]]", "[=").
    */
    bool tableHeaderStart()
    {
        std::size_t at = _pos + 1;
        auto blanks = [&]()
        {
            const std::size_t from = at;
            while ( at < _text.size() &&
                    ( _text[at] == ' ' || _text[at] == '\t' ) )
                ++at;
            return at > from;
        };
        if ( !blanks() && at < _text.size() && _text[at] == '[' )
        {
            ++at;
            blanks();
        }
        if ( at == _text.size() )
            return true;
        const char c = _text[at];
        if ( isBareKeyCharacter( c ) || c == '"' || c == '\'' || c == ']' )
            return true;
        return fail( "invalid TOML: expected a table name (a bare or quoted "
                     "key) after '[', found " +
                         describe( c ),
                     static_cast<int>( at - _pos ) );
    }

    //! A character for messages: 'c', or its name or code.
    static std::string describe( const char c )
    {
        if ( c == '\n' || c == '\r' )
            return "the end of the line";
        const auto u = static_cast<unsigned char>( c );
        if ( u < 0x20 || u >= 0x7f )
        {
            char code[8];
            std::snprintf( code, sizeof code, "0x%02X", u );
            return std::string( "the byte " ) + code;
        }
        return "'" + std::string( 1, c ) + "'";
    }

    std::string_view _text;
    std::shared_ptr<const std::string> _path;
    Diagnostics& _diag;
    std::size_t _pos = 0;
    int _line = 1;
    int _column = 1;
    Lex _lex = Lex::Plain;
    int _dots = 0;
    //! The open '[' and '{', innermost last (the nesting depth; at most
    //! max_nesting_depth + 1: deeper fails).
    struct Open
    {
        char bracket; //!< '[', '{' or 'h' (of a table header)
        int line;
        int column;
    };
    std::vector<Open> _open;
    bool _in_header = false; //!< in the brackets of a table header
    bool _line_blank = true; //!< only blanks so far on the current line
};

} // namespace

//---------------------------------------------------------------------------//
bool prescanToml( const std::string_view text, const std::string& file_name,
                  Diagnostics& diag )
{
    return Scanner( text, file_name, diag ).run();
}

} // namespace Impl
} // namespace mpm
