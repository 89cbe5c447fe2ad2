#ifndef MPM_TEST_MINIMAL_CASE_HPP
#define MPM_TEST_MINIMAL_CASE_HPP

namespace mpm_test
{
//! The smallest complete Mohr-Coulomb case file: a 10 x 4 m block on a
//! 10 x 10 grid of 1 m cells, one quasi-static stage without gravity.
inline const char* const minimal_case = R"(
[case]
name = "minimal"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 1.0
cells = [10, 10]
[[materials]]
name = "soil"
model = "mohr_coulomb"
density_kg_per_m3 = 2000.0
youngs_modulus_pa = 1.0e7
poisson_ratio = 0.3
cohesion_peak_pa = 10.0e3
friction_angle_deg = 30.0
[[bodies]]
material = "soil"
polygon_m = [[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [0.0, 4.0]]
[[stages]]
name = "settle"
type = "quasi_static"
duration_s = 2.0
)";
} // namespace mpm_test

#endif // MPM_TEST_MINIMAL_CASE_HPP
