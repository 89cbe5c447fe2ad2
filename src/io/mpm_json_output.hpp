#ifndef MPM_JSON_OUTPUT_HPP
#define MPM_JSON_OUTPUT_HPP

#include <nlohmann/json.hpp>

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Writes `text` to `path` atomically.

  The text goes to a temporary file in the same folder
  (`<path>.tmp.<pid>`), which is flushed to disk (fsync) and then renamed
  onto `path` with std::rename. Readers see either the old file or the
  complete new one, never a partial file. On failure the temporary file is
  removed and std::runtime_error names the path and the failing operation.
*/
void writeTextAtomically( const std::string& path, const std::string& text );

//---------------------------------------------------------------------------//
/*!
  \brief Writes JSON to `path` via a temporary file in the same folder +
  std::rename (atomic), pretty-printed with an indent of 2 and a final
  newline.

  Invalid UTF-8 in strings is replaced by U+FFFD rather than aborting the
  output.
*/
void writeJsonAtomically( const std::string& path,
                          const nlohmann::json& value );

} // namespace mpm

#endif // MPM_JSON_OUTPUT_HPP
