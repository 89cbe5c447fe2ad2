// The cells an inflow polyline passes through and each cell's share of its
// water (src/case/mpm_polyline_cells.cpp), against lengths worked out by
// hand; the piecewise-linear initial pore-pressure profile.
#include <case/mpm_polyline_cells.hpp>
#include <mpm_test_cases.hpp>
#include <setup/mpm_conditions.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace
{
//! 8 x 6 cells of 0.25 m from the origin.
mpm::GridConfig testGrid() { return mpm_test::gridConfig( 0.25, 8, 6 ); }

int cell( const int i, const int j ) { return i * 6 + j; }

//! Length of line per cell, a piece on a grid line split evenly.
std::map<int, double> lengthPerCell( const std::vector<mpm::PolylinePiece>& p )
{
    std::map<int, double> lengths;
    for ( const mpm::PolylinePiece& piece : p )
    {
        const int count = ( piece.cells[0] >= 0 ) + ( piece.cells[1] >= 0 );
        for ( const int c : piece.cells )
            if ( c >= 0 )
                lengths[c] += piece.length_m / count;
    }
    return lengths;
}

// A horizontal, a vertical and a grid-line segment: the length in each
// cell as measured with a ruler (0.1 .. 0.6 at y = 0.6, down to 0.5, along
// the grid line y = 0.5 to x = 1.0).
TEST( PolylineCells, pieces_follow_the_cells_the_line_crosses )
{
    const std::vector<mpm::Point2> line = {
        { 0.1, 0.6 }, { 0.6, 0.6 }, { 0.6, 0.5 }, { 1.0, 0.5 } };
    const auto pieces =
        mpm::polylinePieces( line, testGrid(), mpm::LineMeasure::AlongLine );
    const auto lengths = lengthPerCell( pieces );
    const std::map<int, double> expected = {
        { cell( 0, 2 ), 0.15 },  { cell( 1, 2 ), 0.25 },
        { cell( 2, 2 ), 0.275 }, { cell( 2, 1 ), 0.075 },
        { cell( 3, 1 ), 0.125 }, { cell( 3, 2 ), 0.125 } };
    ASSERT_EQ( lengths.size(), expected.size() );
    for ( const auto& [c, length] : expected )
        EXPECT_NEAR( lengths.at( c ), length, 1.0e-15 ) << "cell " << c;
    EXPECT_NEAR( mpm::polylineLength( line, mpm::LineMeasure::AlongLine ), 1.0,
                 1.0e-15 );
    // On the horizontal the vertical piece has no length.
    EXPECT_NEAR( mpm::polylineLength( line, mpm::LineMeasure::Horizontal ), 0.9,
                 1.0e-15 );
    const auto flat = lengthPerCell(
        mpm::polylinePieces( line, testGrid(), mpm::LineMeasure::Horizontal ) );
    EXPECT_NEAR( flat.at( cell( 2, 2 ) ), 0.175, 1.0e-15 );
}

// A diagonal: the pieces add up to its length, each cell's piece is the
// chord of the line through it.
TEST( PolylineCells, diagonal_pieces_add_up_to_the_length )
{
    const std::vector<mpm::Point2> line = { { 0.1, 0.05 }, { 1.9, 1.4 } };
    const auto pieces =
        mpm::polylinePieces( line, testGrid(), mpm::LineMeasure::AlongLine );
    double sum = 0.0;
    for ( const auto& piece : pieces )
    {
        sum += piece.length_m;
        EXPECT_GE( piece.cells[0], 0 );
        EXPECT_EQ( piece.cells[1], -1 ); // never along a grid line
    }
    EXPECT_NEAR( sum, std::hypot( 1.8, 1.35 ), 1.0e-14 );
    // The line (slope 0.75) starts in cell (0, 0) and leaves it through
    // x = 0.25, at y = 0.05 + 0.15 * 0.75.
    EXPECT_NEAR( lengthPerCell( pieces ).at( cell( 0, 0 ) ),
                 std::hypot( 0.15, 0.15 * 0.75 ), 1.0e-14 );
}

// Shares: a piece on a grid line goes to the occupied side; pieces in no
// occupied cell (empty cells, outside the grid) are shared by the fed
// cells in proportion to their pieces.
TEST( PolylineCells, shares_give_empty_and_outside_pieces_to_the_fed_cells )
{
    const mpm::GridConfig grid = testGrid();
    // Along the grid line y = 1.0 from x = -0.5 (outside) to x = 0.5, then
    // up to y = 1.25 through the empty cell (2, 4).
    const std::vector<mpm::Point2> line = {
        { -0.5, 1.0 }, { 0.5, 1.0 }, { 0.5, 1.25 } };
    const auto pieces =
        mpm::polylinePieces( line, grid, mpm::LineMeasure::AlongLine );
    // Soil up to y = 1.0: rows 0..3 occupied.
    std::set<int> occupied;
    for ( int i = 0; i < 8; ++i )
        for ( int j = 0; j < 4; ++j )
            occupied.insert( cell( i, j ) );
    const auto shares = mpm::polylineCellShares( pieces, occupied );
    // 0.25 m of line above each of cells (0, 3) and (1, 3), all theirs;
    // the 0.5 m outside and the 0.25 m vertical piece beside the empty
    // cells go to them, half each.
    ASSERT_EQ( shares.size(), 2u );
    EXPECT_NEAR( shares.at( cell( 0, 3 ) ), 0.5, 1.0e-15 );
    EXPECT_NEAR( shares.at( cell( 1, 3 ) ), 0.5, 1.0e-15 );
    // Both sides occupied: halves.
    occupied.insert( cell( 0, 4 ) );
    const auto both = mpm::polylineCellShares( pieces, occupied );
    EXPECT_NEAR( both.at( cell( 0, 3 ) ), both.at( cell( 0, 4 ) ), 1.0e-15 );
    EXPECT_NEAR( both.at( cell( 0, 3 ) ) + both.at( cell( 0, 4 ) ),
                 both.at( cell( 1, 3 ) ), 1.0e-15 );
    // No occupied cell on the line: nothing is fed.
    EXPECT_TRUE( mpm::polylineCellShares( pieces, {} ).empty() );
}

// The initial p_w of a body with a profile: linear between the pairs,
// constant beyond the ends; without one, a + b y.
TEST( InitialPorePressure, profile_is_piecewise_linear_and_constant_beyond )
{
    mpm::BodyConfig body;
    body.initial_pore_pressure_pa = 100.0;
    body.initial_pore_pressure_gradient_pa_per_m = -10.0;
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, 3.0 ), 70.0 );
    body.initial_pore_pressure_profile = {
        { 0.0, 19620.0 }, { 2.0, 0.0 }, { 4.0, -39240.0 } };
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, -1.0 ), 19620.0 );
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, 0.5 ), 14715.0 );
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, 2.0 ), 0.0 );
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, 3.5 ), -29430.0 );
    EXPECT_DOUBLE_EQ( mpm::initialPorePressure( body, 9.0 ), -39240.0 );
}

} // namespace
