#ifndef MPM_TEST_WATER_HPP
#define MPM_TEST_WATER_HPP

#include <records/mpm_run_records.hpp>

#include <string>

namespace mpm_test
{
//! Water volume sum n S V of the points of a snapshot, m^3 per metre.
inline double waterVolume( const mpm::HostSnapshot& snap )
{
    double volume = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
        volume += snap.n[p] * snap.S[p] * snap.vol[p];
    return volume;
}

/*!
  \brief The slope study's soil as a case file's [[materials]] entry
  "soil": linear elastic (E = 10 MPa, nu = 0.33), n = 0.3, k = 4.5e-9 m^2
  (K = 0.044 m/s), the paper's van Genuchten retention.
*/
inline std::string slopeSoilToml()
{
    return R"(
[[materials]]
name = "soil"
model = "linear_elastic"
solid_density_kg_per_m3 = 2700.0
porosity = 0.3
permeability_m2 = 4.5e-9
youngs_modulus_pa = 1.0e7
poisson_ratio = 0.33
[materials.retention]
model = "van_genuchten"
alpha_per_pa = 4.4e-4
n = 3.04
residual_saturation = 0.23
)";
}

/*!
  \brief The slope soil's porosity and permeability with Gardner's law
  (alpha 4 /m of head, residual saturation 0), stiff (E = 100 MPa: the
  exact infiltration solutions' soil is rigid), as [[materials]] "soil",
  followed by rollers on the grid's left and right edges.
*/
inline std::string gardnerSoilOnRollersToml()
{
    return R"(
[[materials]]
name = "soil"
model = "linear_elastic"
solid_density_kg_per_m3 = 2700.0
porosity = 0.3
permeability_m2 = 4.5e-9
youngs_modulus_pa = 1.0e8
poisson_ratio = 0.0
[materials.retention]
model = "gardner"
alpha_per_m = 4.0
residual_saturation = 0.0
[[boundaries]]
where = "left"
condition = "fix_x"
[[boundaries]]
where = "right"
condition = "fix_x"
)";
}

} // namespace mpm_test

#endif // MPM_TEST_WATER_HPP
