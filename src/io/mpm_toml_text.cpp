#include <io/mpm_toml_text.hpp>

#include <cstdio>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
bool endsWithDate( const std::string_view text, const std::size_t pos )
{
    if ( pos < 10 )
        return false;
    const std::string_view date = text.substr( pos - 10, 10 );
    for ( std::size_t k = 0; k < date.size(); ++k )
        if ( ( k == 4 || k == 7 ) ? date[k] != '-'
                                  : !isDecimalDigit( date[k] ) )
            return false;
    return true;
}

//---------------------------------------------------------------------------//
std::string describeCharacter( const char c )
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

//---------------------------------------------------------------------------//
std::string timeAfterDateProblem( const std::string_view text,
                                  const std::size_t pos )
{
    if ( pos + 1 >= text.size() || !endsWithDate( text, pos ) )
        return "";
    const char separator = text[pos];
    const char next = text[pos + 1];
    const std::string expected =
        "invalid TOML: expected a time HH:MM:SS after the date and '" +
        std::string( 1, separator ) + "', found ";
    if ( separator != ' ' )
        return isDecimalDigit( next ) ? ""
                                      : expected + describeCharacter( next );
    if ( !isDecimalDigit( next ) )
        return "";
    const bool hour = pos + 3 < text.size() &&
                      isDecimalDigit( text[pos + 2] ) && text[pos + 3] == ':';
    return hour ? ""
                : expected + "'" + std::string( 1, next ) +
                      "' not followed by a digit and ':'";
}

} // namespace Impl
} // namespace mpm
