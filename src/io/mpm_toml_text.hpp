#ifndef MPM_TOML_TEXT_HPP
#define MPM_TOML_TEXT_HPP

#include <cstddef>
#include <string>
#include <string_view>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Character tests and descriptions of the TOML pre-scan
// (mpm_toml_prescan.cpp). Internal to the case reader.
//---------------------------------------------------------------------------//

//! True for '0' to '9'.
inline bool isDecimalDigit( const char c ) { return c >= '0' && c <= '9'; }

//! True if the 10 characters of `text` before position `pos` read
//! YYYY-MM-DD.
bool endsWithDate( std::string_view text, std::size_t pos );

/*!
  \brief At a 'T', 't' or ' ' at `pos` of a TOML value: the error text if a
  date YYYY-MM-DD before it is not followed by the start of a time, else
  "". toml++ 3.3 breaks the preconditions of its parsers on such text (an
  assertion in debug builds, undefined behaviour in release ones):
  "1978-05-27T:" calls its time parser on the ':' (a fuzzer finding);
  "1979-05-27 7" before a blank or a ',' ']' '}' is read as a date, then
  its value parser is called on that terminator (a fuzzer finding). After
  'T' the time must start with a digit, after ' ' a digit must go on as an
  hour HH:. Such text is never valid TOML.
*/
std::string timeAfterDateProblem( std::string_view text, std::size_t pos );

//! A character for messages: 'c', "the end of the line" or "the byte 0xNN".
std::string describeCharacter( char c );

} // namespace Impl
} // namespace mpm

#endif // MPM_TOML_TEXT_HPP
