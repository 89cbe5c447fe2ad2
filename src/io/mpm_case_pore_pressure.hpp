#ifndef MPM_CASE_PORE_PRESSURE_HPP
#define MPM_CASE_PORE_PRESSURE_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_analysis.hpp>
#include <io/mpm_toml_access.hpp>

namespace mpm
{
namespace Impl
{
/*!
  \brief The initial pore pressure of a [[bodies]] table (two-phase only):
  p_w = a + b y (initial_pore_pressure_pa, ..._gradient_pa_per_m) or a
  tabulated profile initial_pore_pressure_profile = [[y_m, p_w_pa], ...]
  (at least two pairs, y strictly increasing), not both. Internal to the
  case reader.
*/
void readInitialPorePressure( TableReader& r, const Analysis& analysis,
                              BodyConfig& body );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_PORE_PRESSURE_HPP
