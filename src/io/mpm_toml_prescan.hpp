#ifndef MPM_TOML_PRESCAN_HPP
#define MPM_TOML_PRESCAN_HPP

#include <io/mpm_case_diagnostics.hpp>

#include <string>
#include <string_view>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief Check TOML text, before toml++ parses it, for what the parser
  does not survive: keys, arrays and inline tables nested deeper than
  max_nesting_depth (toml++ recurses and overflows the stack), a byte
  outside ASCII outside strings and comments (never valid TOML; toml++
  3.3 reaches __builtin_unreachable on it in debug builds), and invalid
  TOML on which toml++ 3.3 breaks the preconditions of its own parsing
  functions (assertions in debug builds, undefined behaviour in release
  ones; found by tests/fuzz/): a table header whose name does not start
  with a key ("[\n", "[[[a]]]"), a '}' in an array ("e = [}") and a date
  and 'T' without a time ("d = 1978-05-27T:"). Also refused, though valid
  TOML: a character outside ASCII right after a backslash, or after a
  line-ending backslash and the blanks and line breaks it skips, in a
  multi-line basic string (toml++ 3.3 asks whether it is whitespace and
  reaches __builtin_unreachable for most of them).

  Like toml++, the scan opens a string only at a quote that starts a
  value or a key part (after '=', '[', '{', ',', a '.' between key parts
  or at the start of a line); any other quote ("e = 7\"...") is plain text
  to toml++, and so is what follows it.

  Strings and comments are skipped; the nesting depth at a character is
  the number of open '[' and '{' plus the dots of the dotted key it is
  part of. The first problem is reported in diag at its line and column.

  \return Whether the text passed (nothing was reported).
*/
bool prescanToml( std::string_view text, const std::string& file_name,
                  Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_TOML_PRESCAN_HPP
