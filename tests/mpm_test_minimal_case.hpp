#ifndef MPM_TEST_MINIMAL_CASE_HPP
#define MPM_TEST_MINIMAL_CASE_HPP

#include <mpm_test_toml.hpp>

#include <string>

namespace mpm_test
{
//! A dry case `name`: a 10 x 4 m block of `model` soil (2000 kg/m^3,
//! E = 10 MPa, nu = 0.3, then the keys `strength`) on a 10 x 10 grid of
//! 1 m cells, one quasi-static stage of 2 s without gravity.
inline std::string dryBlockCase( const std::string& name,
                                 const std::string& model,
                                 const std::string& strength )
{
    return "\n" + caseToml( name ) + gridToml( "1.0", "[10, 10]" ) +
           dryMaterialToml( "soil", model, "2000.0", "1.0e7", "0.3" ) +
           strength + soilBodyToml( rectangleToml( "10.0", "4.0" ) ) +
           stageToml( "settle", "quasi_static", "2.0" );
}

//! The smallest complete Mohr-Coulomb case file (dryBlockCase "minimal").
inline const std::string minimal_case =
    dryBlockCase( "minimal", "mohr_coulomb",
                  "cohesion_peak_pa = 10.0e3\nfriction_angle_deg = 30.0\n" );
} // namespace mpm_test

#endif // MPM_TEST_MINIMAL_CASE_HPP
