#include <mpm_test_cli.hpp>
#include <mpm_test_toml.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

// The quasi-static scheme (docs/formulation.md §11) stops when the skeleton
// finds no equilibrium, and not when it finds one.
namespace
{
namespace fs = std::filesystem;

//! A saturated 1 m x 2 m block of Mohr-Coulomb soil (phi = 30 deg, cohesion
//! `cohesion_pa`) standing free on a fixed base under gravity, 0.25 m cells,
//! the quasi-static scheme with at most `max_steps` relaxation steps, one
//! hour.
std::string freeBlockCase( const std::string& cohesion_pa,
                           const std::string& max_steps )
{
    return "\n" + mpm_test::caseToml( "free_block", "saturated" ) +
           mpm_test::gridToml( "0.25", "[16, 12]" ) +
           "[[materials]]\nname = \"soil\"\nmodel = \"mohr_coulomb\"\n"
           "solid_density_kg_per_m3 = 2650.0\nporosity = 0.3\n"
           "permeability_m2 = 1.0e-13\nyoungs_modulus_pa = 1.0e7\n"
           "poisson_ratio = 0.3\nfriction_angle_deg = 30.0\n"
           "cohesion_peak_pa = " +
           cohesion_pa + "\n" +
           mpm_test::soilBodyToml(
               "[[1.5, 0.0], [2.5, 0.0], [2.5, 2.0], [1.5, 2.0]]" ) +
           mpm_test::boundaryToml( "bottom", "fixed" ) +
           "[solver]\nscheme = \"quasi_static\"\nrelaxation_max_steps = " +
           max_steps + "\nseepage_initial_dt_s = 600.0\n" +
           mpm_test::stageToml( "stand", "quasi_static", "3600.0" ) +
           "gravity_m_per_s2 = [0.0, -9.81]\n";
}

// A cohesionless block cannot stand with vertical faces: the relaxation
// never comes to rest and the run stops at once, naming the time, the
// speed and the scheme that follows a failure.
TEST( QuasiStaticFailure, a_collapsing_block_stops_the_run_with_a_diagnosis )
{
    const fs::path dir = mpm_test::freshTempDir( "quasi_static_collapse" );
    const fs::path file =
        mpm_test::writeCase( dir, freeBlockCase( "0.0", "600" ) );
    const auto result =
        mpm_test::runCommand( mpm_test::runArgs( file, dir / "out" ) );
    EXPECT_EQ( result.exit_code, 1 ) << result.output;
    for ( const char* fragment :
          { "the skeleton found no equilibrium at t = 0 s",
            "after 600 relaxation steps", "the soil is failing",
            "semi_implicit" } )
        EXPECT_NE( result.output.find( fragment ), std::string::npos )
            << fragment << "\n"
            << result.output;
}

// With 20 kPa of cohesion the same block stands (c / (gamma H) = 0.5): the
// hour of the stage runs to its end.
TEST( QuasiStaticFailure, a_block_that_stands_runs_its_stage )
{
    const fs::path dir = mpm_test::freshTempDir( "quasi_static_stands" );
    const fs::path file =
        mpm_test::writeCase( dir, freeBlockCase( "20.0e3", "20000" ) );
    const auto result =
        mpm_test::runCommand( mpm_test::runArgs( file, dir / "out" ) );
    EXPECT_EQ( result.exit_code, 0 ) << result.output;
    EXPECT_TRUE( fs::exists( dir / "out" / "particles.h5" ) );
}

} // namespace
