#include <io/mpm_case_limits.hpp>
#include <io/mpm_toml_prescan.hpp>

#include <memory>

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
            }
            else
                ++_column;
        }
    }

    bool fail( const std::string& text )
    {
        toml::source_region where;
        where.begin = { static_cast<toml::source_index>( _line ),
                        static_cast<toml::source_index>( _column ) };
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
        case '{':
            ++_depth;
            _dots = 0;
            break;
        case ']':
        case '}':
            _depth = _depth > 0 ? _depth - 1 : 0;
            _dots = 0;
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
        if ( _depth + _dots > max_nesting_depth )
            return fail( "invalid case file: keys, arrays and inline tables "
                         "nested deeper than " +
                         std::to_string( max_nesting_depth ) +
                         " levels (dotted key parts, '[' and '{' counted)" );
        advance();
        return true;
    }

    std::string_view _text;
    std::shared_ptr<const std::string> _path;
    Diagnostics& _diag;
    std::size_t _pos = 0;
    int _line = 1;
    int _column = 1;
    Lex _lex = Lex::Plain;
    int _depth = 0;
    int _dots = 0;
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
