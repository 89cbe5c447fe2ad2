#ifndef MPM_CASE_OVERRIDES_HPP
#define MPM_CASE_OVERRIDES_HPP

#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//! At most this many --set overrides per run.
constexpr std::size_t max_overrides = 64;

//---------------------------------------------------------------------------//
/*!
  \brief Apply `rainslide run/check --set KEY=VALUE` overrides to a parsed
  case (its includes resolved), in order, before it is validated.

  KEY is a dotted path as the case reader's messages write it
  (`solver.courant_number`, `stages[1].duration_s`,
  `materials[0].retention.n`); VALUE is a TOML value (`0.5`, `true`,
  `"text"`, `[1.0, 2.0]`). Tables on the path that do not exist are
  created, an array element must exist; the value replaces what is there
  or adds the key. The case reader then checks the result like any case
  (unknown keys, types, ranges): errors on an overridden value name the
  override (`--set KEY=VALUE:1:5: error: ...`). Malformed overrides (no
  `=`, a bad key or value, a path through a value or past an array's end,
  more than max_overrides, longer than max_text_length) are reported in
  diag.
*/
void applyOverrides( toml::table& root,
                     const std::vector<std::string>& overrides,
                     Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_OVERRIDES_HPP
