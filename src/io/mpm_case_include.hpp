#ifndef MPM_CASE_INCLUDE_HPP
#define MPM_CASE_INCLUDE_HPP

#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

#include <cstddef>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief Resolve the top-level `include` key of a case: each listed file
  (a path relative to the including file) is read, its own includes
  resolved, and the including file laid over it: tables merge key by key,
  element i of an array of tables merges into element i of the included
  array (extra elements are appended), any other value replaces the
  included one. Nodes keep their source file, so errors name the file
  that set the key. Unreadable, invalid or circular includes are reported
  in diag, and so are the limits of src/io/mpm_case_limits.hpp: included
  files must be regular files (not a device, FIFO or directory), at most
  max_include_files in all, max_include_depth deep and, with the case
  file, max_case_total_bytes long; a file met again on the chain of
  includes (compared by canonical path) is circular.

  \param root The parsed case file; on return, the merged case without
  the `include` key.
  \param file_name The case file's path (for relative includes).
  \param bytes_read Size of the case file, counted in the byte limit.
*/
void resolveIncludes( toml::table& root, const std::string& file_name,
                      Diagnostics& diag, std::size_t bytes_read = 0 );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_INCLUDE_HPP
