#include <io/mpm_case_limits.hpp>
#include <io/mpm_toml_prescan.hpp>
#include <io/mpm_toml_text.hpp>

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
            {
                _lex = Lex::Plain; // the line break is plain text
                return true;
            }
            break;
        case Lex::Basic:
            if ( c == '\\' )
                advance();
            else if ( c == '\n' )
            {
                _lex = Lex::Plain; // unterminated: toml++ reports it
                return true;
            }
            else if ( c == '"' )
                endString();
            break;
        case Lex::Literal:
            if ( c == '\n' )
            {
                _lex = Lex::Plain;
                return true;
            }
            if ( c == '\'' )
                endString();
            break;
        case Lex::MultiBasic:
            if ( c == '\\' )
            {
                if ( !multiLineEscape() )
                    return false;
                advance();
            }
            else if ( startsWith( "\"\"\"" ) )
            {
                advance( 3 );
                endString();
                return true;
            }
            break;
        case Lex::MultiLiteral:
            if ( startsWith( "'''" ) )
            {
                advance( 3 );
                endString();
                return true;
            }
            break;
        case Lex::Plain:
            return plain( c );
        }
        advance();
        return true;
    }

    void endString()
    {
        _lex = Lex::Plain;
        _prev = '"';
    }

    /*!
      Whether a quote here opens a string for toml++: at the start of a
      value (after '=', '[', ',' or a line break in an array) or of a key
      (at the start of a line, after '[' of a table header, '{' or ',' of an
      inline table, or a '.' between key parts). Elsewhere (after other
      text of a value or key: 'e = 7"..."', 'e = 1."..."') toml++ reads the
      quote as part of the value, and what follows too, outside any string.
    */
    bool opensString( const char prev ) const
    {
        switch ( prev )
        {
        case '\n':
        case '=':
        case '[':
        case '{':
        case ',':
            return true;
        case '.':
            return _key;
        default:
            return false;
        }
    }

    //! At a quote that opens a string: a multi-line one (its delimiter
    //! `multi_delimiter` consumed, true) or a one-line one.
    bool openString( const std::string_view multi_delimiter, const Lex multi,
                     const Lex single )
    {
        if ( startsWith( multi_delimiter ) )
        {
            advance( multi_delimiter.size() );
            _lex = multi;
            return true;
        }
        _lex = single;
        return false;
    }

    bool plain( const char c )
    {
        if ( static_cast<unsigned char>( c ) >= 0x80 )
            return fail( "invalid TOML: a character outside ASCII outside a "
                         "string or comment (only strings and comments may "
                         "hold other characters)" );
        const char prev = _prev;
        if ( c != ' ' && c != '\t' )
            _prev = c;
        switch ( c )
        {
        case '#':
            _lex = Lex::Comment;
            break;
        case '"':
            if ( opensString( prev ) &&
                 openString( "\"\"\"", Lex::MultiBasic, Lex::Basic ) )
                return true;
            break;
        case '\'':
            if ( opensString( prev ) &&
                 openString( "'''", Lex::MultiLiteral, Lex::Literal ) )
                return true;
            break;
        case 'T':
        case 't':
        case ' ':
            if ( !_key )
            {
                const std::string problem = timeAfterDateProblem( _text, _pos );
                if ( !problem.empty() )
                    return fail( problem, 1 );
            }
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
            _key = _in_header; // a table name, or the values of an array
            break;
        case '{':
            _dots = 0;
            _open.push_back( { c, _line, _column } );
            _key = true;
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
            _key = false; // after a value (or a table name)
            break;
        case '.':
            ++_dots;
            break;
        case '=':
            _dots = 0;
            // An '=' after a value's text is part of that (invalid) value
            // for toml++, which reads a quote after it outside any string
            // and reaches __builtin_unreachable on a non-ASCII character
            // there: "x = -805='''...'''" (a fuzzer finding).
            if ( !_key )
                _prev = '0';
            _key = false;
            break;
        case ',':
            _dots = 0;
            _key = !_open.empty() && _open.back().bracket == '{';
            break;
        case '\n':
            _dots = 0;
            if ( _open.empty() )
                _key = true;
            else if ( _open.back().bracket == '[' )
                _key = false;
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
      At a '\\' in a multi-line basic string: toml++ 3.3 asks whether the
      character after it, or after a line-ending backslash the first one
      that is not a blank or a line break, is whitespace, and reaches
      __builtin_unreachable (undefined behaviour in release builds) for
      most characters outside ASCII (U+00A0 to U+0499 among them: Latin-1,
      Greek, Cyrillic). Valid TOML, refused here.
    */
    bool multiLineEscape()
    {
        auto blank = []( const char b )
        { return b == ' ' || b == '\t' || b == '\r' || b == '\n'; };
        std::size_t at = _pos + 1;
        auto outside = [&]()
        {
            return at < _text.size() &&
                   static_cast<unsigned char>( _text[at] ) >= 0x80;
        };
        if ( !outside() )
        {
            if ( at == _text.size() || !blank( _text[at] ) )
                return true;
            while ( at < _text.size() && blank( _text[at] ) )
                ++at;
            if ( !outside() )
                return true;
        }
        // Report at `at`: its line and column.
        const int line = _line, column = _column;
        for ( std::size_t k = _pos; k < at; ++k )
        {
            if ( _text[k] == '\n' )
            {
                ++_line;
                _column = 1;
            }
            else
                ++_column;
        }
        fail( "invalid case file: a character outside ASCII right after a "
              "backslash or a line-ending backslash in a multi-line string, "
              "which the TOML parser (toml++ 3.3) cannot read; start with an "
              "ASCII character there or use a literal string '''...'''" );
        _line = line;
        _column = column;
        return false;
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
                         describeCharacter( c ),
                     static_cast<int>( at - _pos ) );
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
    //! In a key (or table name), not a value: where '.' separates key parts.
    bool _key = true;
    //! The last character of plain text that is not a blank ('"' for the
    //! end of a string, '\n' at the start).
    char _prev = '\n';
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
