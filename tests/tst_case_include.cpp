// Case files that include others (a shared geometry), [probes] and the
// slope study's case files.
#include <io/mpm_case_reader.hpp>
#include <mpm_test_toml.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#ifndef RAINSLIDE_CASES_DIR
#define RAINSLIDE_CASES_DIR "/work/main/cases"
#endif

namespace
{
namespace fs = std::filesystem;

//! A fresh directory for the files of one test.
fs::path freshDir( const std::string& name )
{
    const fs::path dir =
        fs::temp_directory_path() / ( "rainslide_include_" + name );
    fs::remove_all( dir );
    fs::create_directories( dir );
    return dir;
}

void writeFile( const fs::path& path, const std::string& text )
{
    std::ofstream( path ) << text;
}

//! A shared geometry: a 10 x 4 m Mohr-Coulomb block on 0.5 m cells, one
//! dynamic stage.
const std::string geometry =
    "# a shared geometry\n" + mpm_test::gridToml( "0.5", "[20, 10]" ) + "\n" +
    mpm_test::soilBodyToml( mpm_test::rectangleToml( "10.0", "4.0" ) ) + "\n" +
    mpm_test::dryMaterialToml( "soil", "mohr_coulomb", "2000.0", "1.0e7",
                               "0.3" ) +
    "cohesion_peak_pa = 20.0e3\nfriction_angle_deg = 20.0\n\n" +
    mpm_test::stageToml( "gravity", "dynamic", "1.0" );

//! A case `name` that includes the file `included`, then the keys `rest`.
std::string includingCase( const std::string& included, const std::string& name,
                           const std::string& rest = "" )
{
    return mpm_test::tomlString( "include", included ) +
           mpm_test::caseToml( name ) + rest;
}

//! The case read from a fresh folder `folder` holding the shared geometry
//! and the case `name` that includes it, with the keys `rest`.
mpm::CaseConfig readWithGeometry( const std::string& folder,
                                  const std::string& name,
                                  const std::string& rest )
{
    const fs::path dir = freshDir( folder );
    writeFile( dir / "geometry.toml", geometry );
    writeFile( dir / "case.toml",
               includingCase( "geometry.toml", name, rest ) );
    return mpm::readCaseFile( ( dir / "case.toml" ).string() );
}

TEST( CaseInclude, merges_tables_and_arrays_of_tables_by_index )
{
    const mpm::CaseConfig config = readWithGeometry(
        "merge", "merged",
        "[grid]\ncell_size_m = 0.25\ncells = [40, 20]\n[[materials]]\n"
        "friction_angle_deg = 30.0\n" +
            mpm_test::dryMaterialToml( "rock", "linear_elastic", "2500.0",
                                       "1.0e9", "0.25" ) );
    EXPECT_EQ( config.name, "merged" );
    // Scalars of the including file replace the included ones.
    EXPECT_DOUBLE_EQ( config.grid.cell_size_m, 0.25 );
    EXPECT_EQ( config.grid.cells[0], 40 );
    EXPECT_DOUBLE_EQ( config.grid.origin_m[0], 0.0 );
    // Element 0 merged key by key, element 1 appended.
    ASSERT_EQ( config.materials.size(), 2u );
    EXPECT_DOUBLE_EQ( config.materials[0].friction_angle_deg, 30.0 );
    EXPECT_DOUBLE_EQ( config.materials[0].cohesion_peak_pa, 20.0e3 );
    EXPECT_EQ( config.materials[1].name, "rock" );
    ASSERT_EQ( config.bodies.size(), 1u );
    EXPECT_DOUBLE_EQ( config.bodies[0].polygon_m[2][1], 4.0 );
}

TEST( CaseInclude, errors_name_the_file_that_set_the_key )
{
    const fs::path dir = freshDir( "errors" );
    std::string bad_geometry = geometry;
    bad_geometry.replace( bad_geometry.find( "cell_size_m = 0.5" ), 17,
                          "cell_size_m = -1.0" );
    writeFile( dir / "geometry.toml", bad_geometry );
    writeFile( dir / "case.toml", includingCase( "geometry.toml", "x" ) );
    try
    {
        mpm::readCaseFile( ( dir / "case.toml" ).string() );
        FAIL() << "accepted an invalid included file";
    }
    catch ( const mpm::CaseError& e )
    {
        const std::string expected = ( dir / "geometry.toml" ).string() +
                                     ":4:15: error: key 'grid.cell_size_m'";
        EXPECT_EQ( std::string( e.what() ).rfind( expected, 0 ), 0u )
            << e.what();
    }
}

TEST( CaseInclude, nested_includes_resolve_relative_to_each_file )
{
    const fs::path dir = freshDir( "nested" );
    fs::create_directories( dir / "shared" );
    writeFile( dir / "shared" / "geometry.toml", geometry );
    writeFile( dir / "shared" / "base.toml",
               includingCase( "geometry.toml", "base" ) );
    writeFile( dir / "variant.toml",
               includingCase( "shared/base.toml", "variant" ) );
    const mpm::CaseConfig config =
        mpm::readCaseFile( ( dir / "variant.toml" ).string() );
    EXPECT_EQ( config.name, "variant" );
    EXPECT_EQ( config.grid.cells[1], 10 );
}

TEST( CaseInclude, probes_are_read )
{
    const mpm::CaseConfig config = readWithGeometry(
        "probes", "probes",
        "[probes]\ninterval_s = 0.05\npoints = [ { name = \"A\", position_m = "
        "[1.0, 3.5] },\n           { name = \"B\", position_m = [9.0, 3.5] } "
        "]\n" );
    EXPECT_DOUBLE_EQ( config.probes.interval_s, 0.05 );
    ASSERT_EQ( config.probes.points.size(), 2u );
    EXPECT_EQ( config.probes.points[1].name, "B" );
    EXPECT_DOUBLE_EQ( config.probes.points[1].position_m[0], 9.0 );
}

//---------------------------------------------------------------------------//
// The slope study: every case shares the geometry, and a parametric case
// differs from the base case only in its parameter.
TEST( SlopeCases, parametric_cases_differ_from_the_base_in_one_parameter )
{
    const auto base =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_base.toml" );
    ASSERT_EQ( base.materials.size(), 1u );
    EXPECT_EQ( base.probes.points.size(), 4u );
    struct Variant
    {
        const char* file;
        double friction_deg;
        double residual_pa;
    };
    for ( const Variant v : { Variant{ "slope_phi15.toml", 15.0, 100.0 },
                              Variant{ "slope_phi30.toml", 30.0, 100.0 },
                              Variant{ "slope_cr001.toml", 20.0, 10.0 },
                              Variant{ "slope_cr5.toml", 20.0, 5000.0 } } )
    {
        SCOPED_TRACE( v.file );
        const auto c = mpm::readCaseFile( std::string( RAINSLIDE_CASES_DIR ) +
                                          "/" + v.file );
        EXPECT_NE( c.name, base.name );
        const mpm::MaterialConfig& m = c.materials.at( 0 );
        const mpm::MaterialConfig& b = base.materials[0];
        EXPECT_DOUBLE_EQ( m.friction_angle_deg, v.friction_deg );
        EXPECT_DOUBLE_EQ( m.cohesion_residual_pa, v.residual_pa );
        EXPECT_DOUBLE_EQ( m.cohesion_peak_pa, b.cohesion_peak_pa );
        EXPECT_DOUBLE_EQ( m.softening_modulus_pa, b.softening_modulus_pa );
        EXPECT_DOUBLE_EQ( m.permeability_m2, b.permeability_m2 );
        EXPECT_EQ( c.grid.cells, base.grid.cells );
        EXPECT_EQ( c.bodies[0].polygon_m, base.bodies[0].polygon_m );
        EXPECT_EQ( c.stages.size(), base.stages.size() );
    }
}

// An empty array in the including file removes an included list: the
// moving-surface case replaces the base case's p_w = 0 points by rain.
TEST( SlopeCases, rain_on_the_surface_replaces_the_held_surface_pressure )
{
    const auto base =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_base.toml" );
    const auto rain =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_rain_surface.toml" );
    ASSERT_EQ( rain.stages.size(), 2u );
    EXPECT_EQ( base.stages[1].pore_pressures.size(), 1u );
    EXPECT_TRUE( rain.stages[1].pore_pressures.empty() );
    ASSERT_EQ( rain.stages[1].inflows.size(), 1u );
    EXPECT_DOUBLE_EQ( rain.stages[1].inflows[0].follow_surface_interval_s,
                      0.1 );
    // Stage 1 and everything else as in the base case.
    EXPECT_EQ( rain.stages[0].pore_pressures.size(), 1u );
    EXPECT_DOUBLE_EQ( rain.stages[1].duration_s, base.stages[1].duration_s );
}

} // namespace
