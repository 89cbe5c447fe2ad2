#include <case/mpm_geometry.hpp>
#include <io/mpm_case_reader.hpp>
#include <mpm_device_type.hpp>
#include <mpm_test_cases.hpp>
#include <setup/mpm_conditions.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_wall_nodes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
using Node = std::pair<int, int>;

//! A grid of 4 x 3 cells of 1 m from the origin: nodes (0..4, 0..3).
mpm::GridConfig smallGrid() { return mpm_test::gridConfig( 1.0, 4, 3 ); }

std::set<Node> selectedNodes( const mpm::GridConfig& grid,
                              const std::vector<mpm::Point2>& line )
{
    const auto flags = mpm::wallNodes( grid, line );
    const int ny1 = grid.cells[1] + 1;
    std::set<Node> nodes;
    for ( std::size_t n = 0; n < flags.size(); ++n )
        if ( flags[n] )
            nodes.insert(
                { static_cast<int>( n ) / ny1, static_cast<int>( n ) % ny1 } );
    return nodes;
}

//---------------------------------------------------------------------------//
// Hand-checked selections on the 4 x 3 grid of 1 m cells.
TEST( WallNodes, vertical_wall_on_a_grid_line_holds_that_line )
{
    // x = 2 from y = 0 to 2: the nodes on it; (2, 3), (1, *) and (3, *)
    // are one cell away (zero weight on the wall).
    EXPECT_EQ( selectedNodes( smallGrid(), { { 2.0, 0.0 }, { 2.0, 2.0 } } ),
               ( std::set<Node>{ { 2, 0 }, { 2, 1 }, { 2, 2 } } ) );
}

TEST( WallNodes, vertical_wall_between_grid_lines_holds_both_lines )
{
    // x = 1.5 from y = 0.5 to 2.5 crosses the cells of columns 1, rows 0-2.
    std::set<Node> expected;
    for ( int i : { 1, 2 } )
        for ( int j = 0; j <= 3; ++j )
            expected.insert( { i, j } );
    EXPECT_EQ( selectedNodes( smallGrid(), { { 1.5, 0.5 }, { 1.5, 2.5 } } ),
               expected );
}

TEST( WallNodes, horizontal_wall_on_a_grid_line_holds_that_line )
{
    EXPECT_EQ( selectedNodes( smallGrid(), { { 0.0, 1.0 }, { 3.0, 1.0 } } ),
               ( std::set<Node>{ { 0, 1 }, { 1, 1 }, { 2, 1 }, { 3, 1 } } ) );
    // Listed in the other direction: the same nodes.
    EXPECT_EQ( selectedNodes( smallGrid(), { { 3.0, 1.0 }, { 0.0, 1.0 } } ),
               selectedNodes( smallGrid(), { { 0.0, 1.0 }, { 3.0, 1.0 } } ) );
}

TEST( WallNodes, diagonal_wall_holds_the_corners_of_the_cells_it_crosses )
{
    // 30 degrees from (0, 0.5): y = 0.5 + x tan 30, up to y = 2.81 at x = 4.
    // It crosses cells (0,0), (0,1), (1,1), (2,1), (2,2), (3,2) (y = 1 at
    // x = 0.87, y = 2 at x = 2.60): their corners, 14 nodes.
    const double top = 0.5 + 4.0 * std::tan( M_PI / 6.0 );
    const std::set<Node> expected = {
        { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 1 }, { 0, 2 }, { 1, 2 }, { 2, 1 },
        { 2, 2 }, { 3, 1 }, { 3, 2 }, { 2, 3 }, { 3, 3 }, { 4, 2 }, { 4, 3 } };
    EXPECT_EQ( selectedNodes( smallGrid(), { { 0.0, 0.5 }, { 4.0, top } } ),
               expected );
}

//---------------------------------------------------------------------------//
// Largest max-norm distance from p to segment ab (convex in the segment
// parameter: golden-section search), for the minimality check.
double maxNormDistance( const mpm::Point2& a, const mpm::Point2& b,
                        const mpm::Point2& p )
{
    auto at = [&]( const double t )
    {
        return std::max( std::abs( a[0] + t * ( b[0] - a[0] ) - p[0] ),
                         std::abs( a[1] + t * ( b[1] - a[1] ) - p[1] ) );
    };
    double lo = 0.0, hi = 1.0;
    for ( int k = 0; k < 200; ++k )
    {
        const double m1 = lo + ( hi - lo ) * 0.381966;
        const double m2 = hi - ( hi - lo ) * 0.381966;
        if ( at( m1 ) < at( m2 ) )
            hi = m2;
        else
            lo = m1;
    }
    return std::min( { at( lo ), at( 0.0 ), at( 1.0 ) } );
}

// Walls on an offset grid of 0.37 m cells: random ones, ones along grid
// lines, through nodes and on the grid's edges.
std::vector<std::vector<mpm::Point2>> testWalls( const mpm::GridConfig& grid )
{
    const double h = grid.cell_size_m;
    auto node = [&]( const double i, const double j ) {
        return mpm::Point2{ grid.origin_m[0] + i * h,
                            grid.origin_m[1] + j * h };
    };
    std::vector<std::vector<mpm::Point2>> walls = {
        { node( 3, 0 ), node( 3, 5 ) },     // vertical, grid line
        { node( 0, 2 ), node( 7, 2 ) },     // horizontal, grid line
        { node( 1, 1 ), node( 4, 4 ) },     // 45 degrees through nodes
        { node( 0, 0 ), node( 7, 5 ) },     // the grid's diagonal
        { node( 2.5, 0 ), node( 2.5, 5 ) }, // vertical, mid-cell
        { node( 0, 0 ), node( 7, 0 ), node( 7, 5 ) }, // along two edges
        { node( 1, 1 ), node( 6, 1 ), node( 6, 4 ), node( 1, 4 ),
          node( 1, 1 ) }, // a closed box on grid lines
    };
    std::mt19937 random( 12 );
    std::uniform_real_distribution<double> x( 0.0, 7.0 ), y( 0.0, 5.0 );
    for ( int w = 0; w < 40; ++w )
    {
        std::vector<mpm::Point2> line;
        for ( int k = 0; k < 2 + w % 3; ++k )
            line.push_back( node( x( random ), y( random ) ) );
        walls.push_back( line );
    }
    return walls;
}

/*
  The property the rule guarantees, checked independently of it: at points
  densely spaced along each wall (and at its vertices), the bilinear
  weights of the nodes not selected sum to zero (so the grid velocity there
  is the wall's whatever the free nodes carry: no gap); in cell terms, a
  sample inside a cell has the cell's four corners selected. And the
  selection is the smallest with it: every selected node has a max-norm
  distance below one cell to the wall.
*/
TEST( WallNodes, no_free_weight_anywhere_on_a_wall_and_no_node_more )
{
    mpm::GridConfig grid;
    grid.origin_m = { -0.3, 1.1 };
    grid.cell_size_m = 0.37;
    grid.cells = { 7, 5 };
    const double h = grid.cell_size_m;
    const int nx1 = grid.cells[0] + 1, ny1 = grid.cells[1] + 1;
    int checked_samples = 0, checked_cells = 0;
    const auto walls = testWalls( grid );
    for ( std::size_t w = 0; w < walls.size(); ++w )
    {
        const auto& wall = walls[w];
        const auto flags = mpm::wallNodes( grid, wall );
        for ( std::size_t s = 0; s + 1 < wall.size(); ++s )
            for ( int k = 0; k <= 2000; ++k )
            {
                const double t = k / 2000.0;
                const mpm::Point2 p = {
                    wall[s][0] + t * ( wall[s + 1][0] - wall[s][0] ),
                    wall[s][1] + t * ( wall[s + 1][1] - wall[s][1] ) };
                double free_weight = 0.0;
                for ( int i = 0; i < nx1; ++i )
                    for ( int j = 0; j < ny1; ++j )
                    {
                        const double wx =
                            1.0 -
                            std::abs( p[0] - grid.origin_m[0] - i * h ) / h;
                        const double wy =
                            1.0 -
                            std::abs( p[1] - grid.origin_m[1] - j * h ) / h;
                        if ( wx > 0.0 && wy > 0.0 && !flags[i * ny1 + j] )
                            free_weight += wx * wy;
                    }
                ASSERT_LT( free_weight, 1.0e-8 )
                    << "a free node has weight at (" << p[0] << ", " << p[1]
                    << ") on wall " << w;
                ++checked_samples;
                // A sample strictly inside a cell: the cell's four corners.
                const double sx = ( p[0] - grid.origin_m[0] ) / h;
                const double sy = ( p[1] - grid.origin_m[1] ) / h;
                const int ci = static_cast<int>( std::floor( sx ) );
                const int cj = static_cast<int>( std::floor( sy ) );
                if ( sx - ci > 1e-6 && sx - ci < 1 - 1e-6 && sy - cj > 1e-6 &&
                     sy - cj < 1 - 1e-6 )
                {
                    for ( int c = 0; c < 4; ++c )
                        ASSERT_TRUE(
                            flags[( ci + ( c & 1 ) ) * ny1 + cj + ( c >> 1 )] )
                            << "cell (" << ci << ", " << cj
                            << ") is crossed but corner " << c << " is free";
                    ++checked_cells;
                }
            }
        for ( int i = 0; i < nx1; ++i )
            for ( int j = 0; j < ny1; ++j )
            {
                if ( !flags[i * ny1 + j] )
                    continue;
                const mpm::Point2 node = { grid.origin_m[0] + i * h,
                                           grid.origin_m[1] + j * h };
                double distance = 1.0e300;
                for ( std::size_t s = 0; s + 1 < wall.size(); ++s )
                    distance = std::min(
                        distance,
                        maxNormDistance( wall[s], wall[s + 1], node ) );
                EXPECT_LT( distance, h )
                    << "node (" << i << ", " << j << ") selected without need";
            }
    }
    EXPECT_GT( checked_samples, 100000 );
    EXPECT_GT( checked_cells, 50000 );
}

//---------------------------------------------------------------------------//
// The condition goes on the wall's nodes; an impermeable wall ties both
// water components there, a drained one changes no tie (the bottom edge's
// stays impermeable at the wall's foot).
TEST( WallNodes, node_flags_and_water_ties_of_a_wall )
{
    const mpm::GridConfig grid = smallGrid();
    const int ny1 = 4;
    mpm::BoundaryConfig wall;
    wall.where = mpm::BoundarySelector::Polyline;
    wall.condition = mpm::BoundaryCondition::FixX;
    wall.polyline_m = { { 2.0, 0.0 }, { 2.0, 2.0 } };
    const auto flags = mpm::nodeFlags( grid, { wall } );
    EXPECT_EQ( flags[2 * ny1 + 1], mpm::node_fix_x );
    EXPECT_EQ( flags[2 * ny1 + 3], mpm::node_free );
    EXPECT_EQ( flags[1 * ny1 + 1], mpm::node_free );

    const auto impermeable = mpm::waterNodeFlags( grid, { wall } );
    EXPECT_EQ( impermeable[2 * ny1 + 1], mpm::node_fixed );
    EXPECT_EQ( impermeable[2 * ny1 + 0], mpm::node_fixed );
    EXPECT_EQ( impermeable[1 * ny1 + 1], mpm::node_free );
    wall.hydraulic = mpm::HydraulicCondition::Drained;
    const auto drained = mpm::waterNodeFlags( grid, { wall } );
    EXPECT_EQ( drained[2 * ny1 + 1], mpm::node_free );
    EXPECT_EQ( drained[2 * ny1 + 0], mpm::node_fix_y ); // the bottom edge's
    EXPECT_EQ( drained, mpm::waterNodeFlags( grid, {} ) );

    // interiorWalls splits a list into walls and the rest, in order.
    mpm::BoundaryConfig bottom;
    bottom.where = mpm::BoundarySelector::Bottom;
    const auto walls = mpm::interiorWalls( { bottom, wall, bottom }, true );
    const auto others = mpm::interiorWalls( { bottom, wall, bottom }, false );
    ASSERT_EQ( walls.size(), 1u );
    EXPECT_EQ( walls[0].where, mpm::BoundarySelector::Polyline );
    EXPECT_EQ( others.size(), 2u );
}

//---------------------------------------------------------------------------//
TEST( WallNodes, segment_meets_open_square )
{
    using mpm::geometry::segmentMeetsOpenSquare;
    const mpm::Point2 c = { 0.0, 0.0 };
    // Through, touching the edge only, degenerate inside and outside.
    EXPECT_TRUE( segmentMeetsOpenSquare( { -2, 0.5 }, { 2, 0.5 }, c, 1.0 ) );
    EXPECT_FALSE( segmentMeetsOpenSquare( { -2, 1.0 }, { 2, 1.0 }, c, 1.0 ) );
    EXPECT_FALSE( segmentMeetsOpenSquare( { 1.0, -2 }, { 1.0, 2 }, c, 1.0 ) );
    EXPECT_TRUE( segmentMeetsOpenSquare( { 0.2, 0.3 }, { 0.2, 0.3 }, c, 1.0 ) );
    EXPECT_FALSE(
        segmentMeetsOpenSquare( { 1.2, 0.3 }, { 1.2, 0.3 }, c, 1.0 ) );
    // Passing the corner diagonally (x + y = 2 - eps) and just outside it.
    EXPECT_TRUE( segmentMeetsOpenSquare( { 2, -0.01 }, { -0.01, 2 }, c, 1.0 ) );
    EXPECT_FALSE( segmentMeetsOpenSquare( { 2, 0.01 }, { 0.01, 2 }, c, 1.0 ) );
    // Ending before the square.
    EXPECT_FALSE( segmentMeetsOpenSquare( { -3, 0 }, { -1.5, 0 }, c, 1.0 ) );
}

//---------------------------------------------------------------------------//
// Reader: interior walls in a two-phase case (impermeable by default,
// vertical segments and any direction allowed) and the static stop's
// speed_percentile (default 100), through overrides.
TEST( WallNodes, reader_takes_walls_and_the_speed_percentile )
{
    std::ifstream in( RAINSLIDE_TEST_DATA_DIR "/good_two_phase_case.toml" );
    std::stringstream text;
    text << in.rdbuf();
    text << "\n[[boundaries]]\nwhere = \"polyline\"\n"
            "polyline_m = [[0.1, 0.0], [0.1, 0.5], [0.15, 0.45]]\n"
            "condition = \"fix_x\"\n"
            "\n[[boundaries]]\nwhere = \"polyline\"\n"
            "polyline_m = [[0.2, 0.8], [0.0, 0.8]]\n"
            "condition = \"none\"\nhydraulic = \"drained\"\n";
    const auto c =
        mpm::parseCase( text.str(), "walls.toml",
                        { "stages[1].static_stop.static_speed_m_per_s=0.01" } );
    ASSERT_EQ( c.boundaries.size(), 6u );
    const auto& wall = c.boundaries[4];
    EXPECT_EQ( wall.where, mpm::BoundarySelector::Polyline );
    EXPECT_EQ( wall.condition, mpm::BoundaryCondition::FixX );
    EXPECT_EQ( wall.hydraulic, mpm::HydraulicCondition::Impermeable );
    ASSERT_EQ( wall.polyline_m.size(), 3u );
    EXPECT_EQ( wall.polyline_m[2][0], 0.15 );
    const auto& screen = c.boundaries[5];
    EXPECT_FALSE( screen.constrains_solid );
    EXPECT_EQ( screen.hydraulic, mpm::HydraulicCondition::Drained );
    // The first stage inherits the case list; the second has its own.
    EXPECT_EQ( c.stages[0].boundaries.size(), 6u );
    EXPECT_EQ( c.stages[1].boundaries.size(), 1u );
    EXPECT_EQ( c.stages[1].static_stop.speed_percentile, 100.0 );

    const auto p95 =
        mpm::parseCase( text.str(), "walls.toml",
                        { "stages[1].static_stop.static_speed_m_per_s=0.01",
                          "stages[1].static_stop.speed_percentile=95" } );
    EXPECT_EQ( p95.stages[1].static_stop.speed_percentile, 95.0 );
    for ( const char* bad : { "0", "100.5", "-3" } )
        EXPECT_THROW(
            mpm::parseCase( text.str(), "walls.toml",
                            { "stages[1].static_stop.static_speed_m_per_s=0.01",
                              std::string( "stages[1].static_stop."
                                           "speed_percentile=" ) +
                                  bad } ),
            mpm::CaseError )
            << bad;
}

} // namespace
