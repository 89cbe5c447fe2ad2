#ifndef MPM_CASE_PROBES_HPP
#define MPM_CASE_PROBES_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief Read the [probes] table (tracked points): interval_s and
  [[probes.points]] with a unique name and a position inside the grid
  (grid null if the grid itself is invalid).
*/
ProbesConfig readProbes( const toml::table& table, const GridConfig* grid,
                         Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_PROBES_HPP
