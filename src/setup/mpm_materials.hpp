#ifndef MPM_MATERIALS_HPP
#define MPM_MATERIALS_HPP

#include <io/mpm_case_config.hpp>
#include <physics/mpm_material_params.hpp>

#include <vector>

namespace mpm
{
//! Kernel-side material table (SI, radians) from the case's materials.
physics::MaterialTable
makeMaterialTable( const std::vector<MaterialConfig>& materials );

} // namespace mpm

#endif // MPM_MATERIALS_HPP
