#ifndef MPM_MATERIALS_HPP
#define MPM_MATERIALS_HPP

#include <case/mpm_case_config.hpp>
#include <physics/mpm_material_params.hpp>

#include <vector>

namespace mpm
{
//! Kernel-side retention parameters (SI); water_unit_weight = rho_w g
//! converts pressure to head for Gardner's law.
physics::RetentionParams retentionParams( const RetentionConfig& config,
                                          double water_unit_weight = 9810.0 );

//! Kernel-side material table (SI, radians) from the case's materials.
physics::MaterialTable
makeMaterialTable( const std::vector<MaterialConfig>& materials );

} // namespace mpm

#endif // MPM_MATERIALS_HPP
