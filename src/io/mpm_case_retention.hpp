#ifndef MPM_CASE_RETENTION_HPP
#define MPM_CASE_RETENTION_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// [materials.retention]: the soil-water retention law of a material in an
// unsaturated analysis. Internal to the case reader.
//---------------------------------------------------------------------------//

//! \brief Every key allowed in a retention table.
std::vector<std::string> retentionKeys();

/*!
  \brief Read and check a whole retention table at path (e.g.
  "materials[0].retention"): the model, the keys it needs, the keys it does
  not use and saturated_saturation > residual_saturation. Returns the law
  with defaults applied, or nothing after reporting errors.
*/
std::optional<RetentionConfig> readRetention( const toml::table& table,
                                              const std::string& path,
                                              Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_RETENTION_HPP
