#ifndef MPM_TEST_WATER_HPP
#define MPM_TEST_WATER_HPP

#include <mpm_test_toml.hpp>

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
    return "\n" + twoPhaseSoilToml( "2700.0", "4.5e-9", "1.0e7", "0.33" ) +
           paperRetentionToml();
}

/*!
  \brief The slope soil's porosity and permeability with Gardner's law
  (alpha 4 /m of head, residual saturation 0), stiff (E = 100 MPa: the
  exact infiltration solutions' soil is rigid), as [[materials]] "soil",
  followed by rollers on the grid's left and right edges.
*/
inline std::string gardnerSoilOnRollersToml()
{
    return "\n" + twoPhaseSoilToml( "2700.0", "4.5e-9", "1.0e8", "0.0" ) +
           "[materials.retention]\nmodel = \"gardner\"\nalpha_per_m = 4.0\n"
           "residual_saturation = 0.0\n" +
           rollersToml();
}

} // namespace mpm_test

#endif // MPM_TEST_WATER_HPP
