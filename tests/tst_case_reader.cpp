#include <io/mpm_case_reader.hpp>
#include <setup/mpm_geometry.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef RAINSLIDE_TEST_DATA_DIR
#define RAINSLIDE_TEST_DATA_DIR "/work/main/tests/data"
#endif

namespace
{
using mpm::Point2;
namespace geo = mpm::geometry;

const std::vector<Point2> unit_square = {
    { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 }, { 0.0, 1.0 } };

// L-shape: the 2 x 2 square minus its upper-right quarter (area 3).
const std::vector<Point2> l_shape = { { 0.0, 0.0 }, { 2.0, 0.0 },
                                      { 2.0, 1.0 }, { 1.0, 1.0 },
                                      { 1.0, 2.0 }, { 0.0, 2.0 } };

//---------------------------------------------------------------------------//
// Geometry.
//---------------------------------------------------------------------------//
TEST( Geometry, point_in_square_either_orientation )
{
    std::vector<Point2> clockwise( unit_square.rbegin(), unit_square.rend() );
    for ( const auto& polygon : { unit_square, clockwise } )
    {
        EXPECT_TRUE( geo::pointInPolygon( polygon, { 0.5, 0.5 } ) );
        EXPECT_TRUE( geo::pointInPolygon( polygon, { 0.01, 0.99 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { 1.5, 0.5 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { 0.5, -0.1 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { -3.0, 0.5 } ) );
    }
}

TEST( Geometry, repeated_closing_vertex_is_ignored )
{
    auto closed = unit_square;
    closed.push_back( closed.front() );
    EXPECT_TRUE( geo::pointInPolygon( closed, { 0.5, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( closed, { 1.5, 0.5 } ) );
    EXPECT_DOUBLE_EQ( geo::polygonArea( closed ), 1.0 );
    int a = -1, b = -1;
    EXPECT_FALSE( geo::findSelfIntersection( closed, a, b ) );
}

TEST( Geometry, concave_l_shape )
{
    EXPECT_TRUE( geo::pointInPolygon( l_shape, { 0.5, 1.5 } ) );
    EXPECT_TRUE( geo::pointInPolygon( l_shape, { 1.5, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( l_shape, { 1.5, 1.5 } ) ); // notch
    EXPECT_DOUBLE_EQ( geo::polygonArea( l_shape ), 3.0 );
    std::vector<Point2> clockwise( l_shape.rbegin(), l_shape.rend() );
    EXPECT_DOUBLE_EQ( geo::polygonArea( clockwise ), 3.0 );
    int a = -1, b = -1;
    EXPECT_FALSE( geo::findSelfIntersection( l_shape, a, b ) );
    EXPECT_FALSE( geo::findSelfIntersection( clockwise, a, b ) );
}

TEST( Geometry, bow_tie_intersects_itself )
{
    const std::vector<Point2> bow_tie = {
        { 0.0, 0.0 }, { 1.0, 1.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } };
    int a = -1, b = -1;
    ASSERT_TRUE( geo::findSelfIntersection( bow_tie, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 2 );
    // Even-odd rule: both lobes are inside, the gap between them is not.
    EXPECT_TRUE( geo::pointInPolygon( bow_tie, { 0.1, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( bow_tie, { 0.5, 0.9 } ) );
}

TEST( Geometry, touching_and_folding_edges_count_as_intersection )
{
    int a = -1, b = -1;
    // Vertex 3 touches edge 0 (non-adjacent edges touch).
    const std::vector<Point2> touching = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 2.0 }, { 1.0, 0.0 }, { 0.0, 2.0 } };
    ASSERT_TRUE( geo::findSelfIntersection( touching, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 2 );
    // Edge 1 runs back over edge 0 (adjacent, collinear overlap).
    const std::vector<Point2> fold = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 } };
    ASSERT_TRUE( geo::findSelfIntersection( fold, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 1 );
    // Collinear but not folding back: a straight vertex is fine.
    const std::vector<Point2> straight = {
        { 0.0, 0.0 }, { 1.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 } };
    EXPECT_FALSE( geo::findSelfIntersection( straight, a, b ) );
}

TEST( Geometry, polyline_interpolation_and_extrapolation )
{
    const std::vector<Point2> line = {
        { 0.0, 1.0 }, { 10.0, 2.0 }, { 20.0, 0.0 } };
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 5.0 ), 1.5 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 10.0 ), 2.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 15.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 0.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, -4.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 25.0 ), 0.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( { { 3.0, 7.0 } }, 1.0 ), 7.0 );
    EXPECT_THROW( geo::polylineY( {}, 1.0 ), std::invalid_argument );
}

//---------------------------------------------------------------------------//
// Case reader: a valid case.
//---------------------------------------------------------------------------//
TEST( CaseReader, reads_good_case )
{
    const std::string path = RAINSLIDE_TEST_DATA_DIR "/good_case.toml";
    const mpm::CaseConfig c = mpm::readCaseFile( path );
    EXPECT_EQ( c.file, path );
    EXPECT_EQ( c.name, "good_slope-1" );
    EXPECT_EQ( c.description,
               "Dry slope: gravity loading, then strength reduction" );
    EXPECT_EQ( c.grid.origin_m, ( Point2{ -1.0, 0.0 } ) );
    EXPECT_DOUBLE_EQ( c.grid.cell_size_m, 0.5 );
    EXPECT_EQ( c.grid.cells, ( std::array<int, 2>{ 42, 20 } ) );
    EXPECT_EQ( c.points_per_cell_per_direction, 3 );

    // Materials, in file order.
    ASSERT_EQ( c.materials.size(), 2u );
    const mpm::MaterialConfig& soil = c.materials[0];
    EXPECT_EQ( soil.name, "soil" );
    EXPECT_EQ( soil.model, mpm::ModelType::MohrCoulomb );
    EXPECT_DOUBLE_EQ( soil.density_kg_per_m3, 1900.0 );
    EXPECT_DOUBLE_EQ( soil.youngs_modulus_pa, 1.0e7 );
    EXPECT_DOUBLE_EQ( soil.poisson_ratio, 0.33 );
    EXPECT_DOUBLE_EQ( soil.cohesion_peak_pa, 20.0e3 );
    EXPECT_DOUBLE_EQ( soil.cohesion_residual_pa, 100.0 );
    EXPECT_DOUBLE_EQ( soil.softening_modulus_pa, -250e3 );
    EXPECT_DOUBLE_EQ( soil.friction_angle_deg, 20.0 );
    EXPECT_DOUBLE_EQ( soil.dilation_angle_deg, 0.1 );
    EXPECT_EQ( c.materials[1].model, mpm::ModelType::LinearElastic );
    EXPECT_DOUBLE_EQ( c.materials[1].density_kg_per_m3, 2500.0 );

    // Bodies: material ids; the repeated closing vertex is dropped.
    ASSERT_EQ( c.bodies.size(), 2u );
    EXPECT_EQ( c.bodies[0].material, "rock" );
    EXPECT_EQ( c.bodies[0].material_id, 1 );
    EXPECT_EQ( c.bodies[0].polygon_m.size(), 4u );
    EXPECT_EQ( c.bodies[1].material_id, 0 );
    EXPECT_EQ( c.bodies[1].polygon_m.size(), 6u );

    ASSERT_EQ( c.boundaries.size(), 3u );
    EXPECT_EQ( c.boundaries[0].where, mpm::BoundarySelector::Left );
    EXPECT_EQ( c.boundaries[0].condition, mpm::BoundaryCondition::FixX );
    EXPECT_EQ( c.boundaries[2].where, mpm::BoundarySelector::BelowPolyline );
    EXPECT_EQ( c.boundaries[2].condition, mpm::BoundaryCondition::Fixed );
    EXPECT_EQ( c.boundaries[2].polyline_m.size(), 3u );

    // Solver: given values and defaults.
    EXPECT_DOUBLE_EQ( c.solver.courant_number, 0.4 );
    EXPECT_DOUBLE_EQ( c.solver.flip_fraction, 1.0 );
    EXPECT_TRUE( c.solver.bbar );
    EXPECT_DOUBLE_EQ( c.solver.dt_s, 0.0 );
    EXPECT_FALSE( c.solver.remove_points_leaving_grid );
    EXPECT_DOUBLE_EQ( c.solver.instability_speed_factor, 10.0 );

    ASSERT_EQ( c.stages.size(), 2u );
    const mpm::StageConfig& gravity = c.stages[0];
    EXPECT_EQ( gravity.name, "gravity" );
    EXPECT_EQ( gravity.type, mpm::StageType::QuasiStatic );
    EXPECT_DOUBLE_EQ( gravity.damping, 0.7 );
    EXPECT_DOUBLE_EQ( gravity.duration_s, 5.0 );
    EXPECT_DOUBLE_EQ( gravity.ke_ratio_tolerance, 1e-5 );
    EXPECT_DOUBLE_EQ( gravity.snapshot_interval_s, 0.0 );
    EXPECT_TRUE( gravity.reset_displacement );
    EXPECT_EQ( gravity.gravity_m_per_s2, ( Point2{ 0.0, -9.81 } ) );
    // Override: soil is linear elastic in this stage; rock is unchanged.
    ASSERT_EQ( gravity.materials.size(), 2u );
    EXPECT_EQ( gravity.materials[0].model, mpm::ModelType::LinearElastic );
    EXPECT_DOUBLE_EQ( gravity.materials[0].youngs_modulus_pa, 1.0e7 );
    EXPECT_DOUBLE_EQ( gravity.materials[0].cohesion_peak_pa, 0.0 );
    EXPECT_EQ( gravity.materials[1].name, "rock" );
    EXPECT_EQ( gravity.boundaries.size(), 3u );

    const mpm::StageConfig& failure = c.stages[1];
    EXPECT_EQ( failure.type, mpm::StageType::Dynamic );
    EXPECT_DOUBLE_EQ( failure.damping, 0.0 );
    EXPECT_DOUBLE_EQ( failure.duration_s, 10.0 );
    EXPECT_DOUBLE_EQ( failure.snapshot_interval_s, 0.5 );
    EXPECT_FALSE( failure.reset_displacement );
    EXPECT_EQ( failure.materials[0].model, mpm::ModelType::MohrCoulomb );
    EXPECT_DOUBLE_EQ( failure.materials[0].cohesion_peak_pa, 15.0e3 );
    EXPECT_DOUBLE_EQ( failure.materials[0].cohesion_residual_pa, 100.0 );
    EXPECT_DOUBLE_EQ( failure.materials[0].friction_angle_deg, 20.0 );
    ASSERT_EQ( failure.boundaries.size(), 1u );
    EXPECT_EQ( failure.boundaries[0].where, mpm::BoundarySelector::Bottom );
}

//---------------------------------------------------------------------------//
const char* minimal_case = R"(
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

TEST( CaseReader, defaults_of_a_minimal_case )
{
    const mpm::CaseConfig c = mpm::parseCase( minimal_case, "minimal.toml" );
    EXPECT_EQ( c.file, "minimal.toml" );
    EXPECT_EQ( c.points_per_cell_per_direction, 2 );
    EXPECT_TRUE( c.boundaries.empty() );
    // Residual cohesion defaults to the peak; softening and dilation to 0.
    EXPECT_DOUBLE_EQ( c.materials[0].cohesion_residual_pa, 10.0e3 );
    EXPECT_DOUBLE_EQ( c.materials[0].softening_modulus_pa, 0.0 );
    EXPECT_DOUBLE_EQ( c.materials[0].dilation_angle_deg, 0.0 );
    EXPECT_DOUBLE_EQ( c.stages[0].damping, 0.7 );
    EXPECT_DOUBLE_EQ( c.stages[0].ke_ratio_tolerance, 1.0e-4 );
    EXPECT_EQ( c.stages[0].materials.size(), 1u );
    EXPECT_DOUBLE_EQ( c.solver.courant_number, 0.5 );
    EXPECT_DOUBLE_EQ( c.solver.flip_fraction, 0.99 );
}

TEST( CaseReader, reports_every_error_in_file_order )
{
    std::string text = minimal_case;
    text.replace( text.find( "duration_s = 2.0" ), 16, "duration_s = -1" );
    text.replace( text.find( "poisson_ratio = 0.3" ), 19,
                  "poisson_ratio = 0.5" );
    try
    {
        mpm::parseCase( text, "two.toml" );
        FAIL() << "expected a CaseError";
    }
    catch ( const mpm::CaseError& e )
    {
        const std::string msg = e.what();
        EXPECT_EQ( msg,
                   "two.toml:13:17: error: key 'materials[0].poisson_ratio': "
                   "expected a number in [0, 0.5), found 0.5\n"
                   "two.toml:22:14: error: key 'stages[0].duration_s': "
                   "expected a number > 0 s, found -1" );
    }
}

TEST( CaseReader, missing_file_is_reported )
{
    const std::string path = RAINSLIDE_TEST_DATA_DIR "/no_such_case.toml";
    try
    {
        mpm::readCaseFile( path );
        FAIL() << "expected a CaseError";
    }
    catch ( const mpm::CaseError& e )
    {
        EXPECT_NE(
            std::string( e.what() ).find( path + ": error: cannot open" ),
            std::string::npos )
            << e.what();
    }
}

//---------------------------------------------------------------------------//
// Case reader: every file in data/bad_cases/ must be rejected. Its first
// lines hold the expectation:
//   # expect: <fragment of the first error line>
//   # expect-line: <line of the first error>
//---------------------------------------------------------------------------//
std::string headerValue( const std::string& file, const std::string& tag )
{
    std::ifstream in( file );
    std::string line;
    const std::string prefix = "# " + tag + ": ";
    while ( std::getline( in, line ) && line.rfind( "#", 0 ) == 0 )
        if ( line.rfind( prefix, 0 ) == 0 )
            return line.substr( prefix.size() );
    return "";
}

TEST( CaseReader, rejects_every_bad_case )
{
    std::vector<std::string> files;
    for ( const auto& entry : std::filesystem::directory_iterator(
              RAINSLIDE_TEST_DATA_DIR "/bad_cases" ) )
        if ( entry.path().extension() == ".toml" )
            files.push_back( entry.path().string() );
    std::sort( files.begin(), files.end() );
    EXPECT_GE( files.size(), 15u );

    for ( const auto& file : files )
    {
        SCOPED_TRACE( file );
        const std::string fragment = headerValue( file, "expect" );
        const std::string line = headerValue( file, "expect-line" );
        ASSERT_FALSE( fragment.empty() ) << "no '# expect: ' line";
        ASSERT_FALSE( line.empty() ) << "no '# expect-line: ' line";
        try
        {
            mpm::readCaseFile( file );
            ADD_FAILURE() << "accepted a bad case";
        }
        catch ( const mpm::CaseError& e )
        {
            const std::string msg = e.what();
            const std::string first = msg.substr( 0, msg.find( '\n' ) );
            EXPECT_EQ( first.rfind( file + ":" + line + ":", 0 ), 0u )
                << "first error: " << first;
            EXPECT_NE( first.find( fragment ), std::string::npos )
                << "first error: " << first;
        }
    }
}

} // namespace
