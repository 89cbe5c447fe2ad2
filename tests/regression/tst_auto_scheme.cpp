#include <mpm_test_cli.hpp>
#include <mpm_test_toml.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

// The auto scheme (docs/formulation.md §12): quasi-static steps while the
// skeleton finds its equilibrium, the semi-implicit scheme from the last
// equilibrium on once it does not.
namespace
{
namespace fs = std::filesystem;

//! A saturated 1 m x 2 m block of Mohr-Coulomb soil (phi = 30 deg, cohesion
//! `cohesion_pa`) standing free on a fixed base under gravity, 0.25 m cells,
//! a dynamic stage of `duration_s` run by `scheme`.
std::string freeBlockCase( const std::string& cohesion_pa,
                           const std::string& scheme,
                           const std::string& duration_s )
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
           "[solver]\nscheme = \"" + scheme +
           "\"\nrelaxation_max_steps = 600\nseepage_initial_dt_s = 600.0\n" +
           mpm_test::stageToml( "stand", "dynamic", duration_s ) +
           "gravity_m_per_s2 = [0.0, -9.81]\n";
}

//! Runs `text` on `backend` into `dir`/out and returns its metrics.json.
nlohmann::json runMetrics( const fs::path& dir, const std::string& text,
                           const std::string& backend )
{
    const fs::path file = mpm_test::writeCase( dir, text );
    const auto result = mpm_test::runCommand(
        "run " + file.string() + " --out " + ( dir / "out" ).string() +
        " --backend " + backend + " --threads 2" );
    EXPECT_EQ( result.exit_code, 0 ) << result.output;
    std::ifstream in( dir / "out" / "metrics.json" );
    return nlohmann::json::parse( in );
}

//! The numbers two runs of the same case must share.
void expectSameRun( const nlohmann::json& a, const nlohmann::json& b )
{
    EXPECT_EQ( a["steps"], b["steps"] );
    EXPECT_EQ( a["simulated_time_s"], b["simulated_time_s"] );
    EXPECT_EQ( a["deformation"]["max_displacement_m"],
               b["deformation"]["max_displacement_m"] );
    EXPECT_EQ( a["water_balance"]["stored_end"],
               b["water_balance"]["stored_end"] );
}

// A cohesionless block cannot stand with vertical faces: the first
// quasi-static step finds no equilibrium, the points go back to the start
// and the semi-implicit scheme runs the collapse from there, bit for bit
// as a semi-implicit run of the case (which it would not if any point or
// cell field kept a trace of the step given up).
TEST( AutoScheme,
      a_collapse_is_the_semi_implicit_run_from_the_last_equilibrium )
{
    for ( const std::string backend : { "serial", "openmp" } )
    {
        const nlohmann::json automatic =
            runMetrics( mpm_test::freshTempDir( "auto_collapse_" + backend ),
                        freeBlockCase( "0.0", "auto", "2.0" ), backend );
        const nlohmann::json dynamic = runMetrics(
            mpm_test::freshTempDir( "semi_collapse_" + backend ),
            freeBlockCase( "0.0", "semi_implicit", "2.0" ), backend );
        expectSameRun( automatic, dynamic );
        EXPECT_GT( automatic["deformation"]["max_displacement_m"].get<double>(),
                   0.05 );
        const nlohmann::json& record = automatic["auto"];
        ASSERT_EQ( record["switches"].size(), 1u ) << record.dump( 1 );
        EXPECT_EQ( record["switches"][0]["time_s"], 0.0 );
        EXPECT_EQ( record["switches"][0]["to"], "semi_implicit" );
        EXPECT_NE( record["switches"][0]["reason"].get<std::string>().find(
                       "no equilibrium" ),
                   std::string::npos );
        EXPECT_EQ( record["quasi_static"]["steps"], 0 );
        EXPECT_EQ( record["semi_implicit"]["steps"], automatic["steps"] );
    }
}

// With 20 kPa of cohesion the block stands: every step of the hour is
// quasi-static, none dynamic, bit for bit as the quasi-static scheme.
TEST( AutoScheme, a_block_that_stands_is_the_quasi_static_run )
{
    for ( const std::string backend : { "serial", "openmp" } )
    {
        const nlohmann::json automatic =
            runMetrics( mpm_test::freshTempDir( "auto_stands_" + backend ),
                        freeBlockCase( "20.0e3", "auto", "3600.0" ), backend );
        const nlohmann::json quasi_static = runMetrics(
            mpm_test::freshTempDir( "quasi_static_stands_" + backend ),
            freeBlockCase( "20.0e3", "quasi_static", "3600.0" ), backend );
        expectSameRun( automatic, quasi_static );
        const nlohmann::json& record = automatic["auto"];
        EXPECT_EQ( record["switches"].size(), 0u ) << record.dump( 1 );
        EXPECT_EQ( record["semi_implicit"]["steps"], 0 );
        EXPECT_EQ( record["quasi_static"]["steps"], automatic["steps"] );
        EXPECT_GT( automatic["steps"].get<long>(), 0 );
    }
}

// The auto scheme's two schemes choose their own steps: a fixed step is
// refused before any work, naming the key; a strength reduction is refused.
TEST( AutoScheme, a_fixed_step_and_a_strength_reduction_are_refused )
{
    const fs::path dir = mpm_test::freshTempDir( "auto_refused" );
    const fs::path file = mpm_test::writeCase(
        dir, freeBlockCase( "20.0e3", "auto", "10.0" ) + "" );
    const auto fixed = mpm_test::runCommand(
        mpm_test::runArgs( file, dir / "out", " --set solver.dt_s=1.0" ) );
    EXPECT_EQ( fixed.exit_code, 2 ) << fixed.output;
    EXPECT_NE( fixed.output.find( "key 'solver.dt_s'" ), std::string::npos )
        << fixed.output;
    EXPECT_NE( fixed.output.find( "expected 0" ), std::string::npos )
        << fixed.output;
    EXPECT_FALSE( fs::exists( dir / "out" ) );
    const auto fos = mpm_test::runCommand( "fos " + file.string() + " --out " +
                                           ( dir / "fos" ).string() );
    EXPECT_EQ( fos.exit_code, 2 ) << fos.output;
    EXPECT_NE( fos.output.find( "found \"auto\"" ), std::string::npos )
        << fos.output;
}

} // namespace
