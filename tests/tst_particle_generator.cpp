#include <mpm_device_type.hpp>
#include <setup/mpm_particle_generator.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
mpm::CaseConfig twoBodyCase( const int n )
{
    mpm::CaseConfig c;
    c.grid.origin_m = { -1.0, 0.0 };
    c.grid.cell_size_m = 0.5;
    c.grid.cells = { 10, 6 };
    c.points_per_cell_per_direction = n;
    mpm::BodyConfig lower, upper;
    lower.material_id = 0;
    lower.polygon_m = {
        { -1.0, 0.0 }, { 4.0, 0.0 }, { 4.0, 1.0 }, { -1.0, 1.0 } };
    upper.material_id = 1;
    // A right triangle on top of the lower block: legs 2 m and 1 m.
    upper.polygon_m = { { 0.0, 1.0 }, { 2.0, 1.0 }, { 0.0, 2.0 } };
    c.bodies = { lower, upper };
    return c;
}

// n x n points per cell at Gauss positions, volume h^2 / n^2, only inside.
TEST( ParticleGenerator, fills_polygons_with_gauss_points )
{
    for ( const int n : { 1, 2, 3 } )
    {
        const auto points = mpm::generatePoints( twoBodyCase( n ) );
        int lower = 0, upper = 0;
        double upper_volume = 0.0;
        for ( int p = 0; p < points.size(); ++p )
        {
            EXPECT_DOUBLE_EQ( points.vol[p], 0.25 / ( n * n ) );
            if ( points.material[p] == 0 )
            {
                ++lower;
                EXPECT_LT( points.x[2 * p + 1], 1.0 );
            }
            else
            {
                ++upper;
                upper_volume += points.vol[p];
                // Inside the triangle x / 2 + (y - 1) <= 1.
                EXPECT_LE( points.x[2 * p] / 2.0 + points.x[2 * p + 1] - 1.0,
                           1.0 );
            }
        }
        // The block covers 10 x 2 cells exactly.
        EXPECT_EQ( lower, 20 * n * n ) << "n = " << n;
        // The triangle's area is 1 m^2; the point volumes approximate it.
        EXPECT_NEAR( upper_volume, 1.0, 0.3 ) << "n = " << n;
        EXPECT_GT( upper, 0 );
    }
    // Gauss positions for n = 2: (0.5 -+ 0.5/sqrt(3)) h inside the first cell.
    const auto points = mpm::generatePoints( twoBodyCase( 2 ) );
    EXPECT_NEAR( points.x[0], -1.0 + 0.5 * ( 0.5 - 0.5 / std::sqrt( 3.0 ) ),
                 1e-14 );
    EXPECT_NEAR( points.x[1], 0.5 * ( 0.5 - 0.5 / std::sqrt( 3.0 ) ), 1e-14 );
}

// The points come column of cells by column (x-major, as the nodes' flat
// index), a cell's n x n points together, row by row within it; the two
// bodies' points interleave where they share a column.
TEST( ParticleGenerator, orders_points_by_cell_column )
{
    const auto points = mpm::generatePoints( twoBodyCase( 2 ) );
    const double h = 0.5;
    long previous = -1;
    int columns_with_both_bodies = 0, last_column = -1;
    bool column_has[2] = { false, false };
    for ( int p = 0; p < points.size(); ++p )
    {
        const int ci =
            static_cast<int>( std::floor( ( points.x[2 * p] + 1.0 ) / h ) );
        const int cj =
            static_cast<int>( std::floor( points.x[2 * p + 1] / h ) );
        const long key = ci * 6L + cj;
        ASSERT_GE( key, previous ) << "point " << p;
        if ( key == previous )
        {
            // Within a cell: row by row, left to right.
            const double dy = points.x[2 * p + 1] - points.x[2 * p - 1];
            const double dx = points.x[2 * p] - points.x[2 * p - 2];
            EXPECT_TRUE( dy > 1e-12 || ( std::abs( dy ) < 1e-12 && dx > 0.0 ) )
                << "point " << p;
        }
        previous = key;
        if ( ci != last_column )
        {
            columns_with_both_bodies += column_has[0] && column_has[1];
            column_has[0] = column_has[1] = false;
            last_column = ci;
        }
        column_has[points.material[p]] = true;
    }
    columns_with_both_bodies += column_has[0] && column_has[1];
    EXPECT_EQ( columns_with_both_bodies, 4 ); // the triangle's x in [0, 2]
}

// Boundary selectors and conditions combine into node flag masks.
TEST( ParticleGenerator, node_flags_from_boundaries )
{
    mpm::GridConfig grid;
    grid.origin_m = { 0.0, 0.0 };
    grid.cell_size_m = 1.0;
    grid.cells = { 4, 3 };
    mpm::BoundaryConfig left, base;
    left.where = mpm::BoundarySelector::Left;
    left.condition = mpm::BoundaryCondition::FixX;
    base.where = mpm::BoundarySelector::BelowPolyline;
    base.condition = mpm::BoundaryCondition::Fixed;
    base.polyline_m = { { 0.0, 2.0 }, { 4.0, 0.0 } }; // y = 2 - x / 2
    const auto flags = mpm::nodeFlags( grid, { left, base } );
    const int ny1 = 4;
    auto at = [&]( int i, int j ) { return flags[i * ny1 + j]; };
    EXPECT_EQ( at( 0, 3 ), mpm::node_fix_x ); // left edge, above the line
    EXPECT_EQ( at( 0, 2 ), mpm::node_fixed ); // on the line (y = 2 at x = 0)
    EXPECT_EQ( at( 2, 1 ), mpm::node_fixed ); // on the line (y = 1 at x = 2)
    EXPECT_EQ( at( 2, 2 ), mpm::node_free );  // above the line
    EXPECT_EQ( at( 3, 0 ), mpm::node_fixed ); // below the line
    EXPECT_EQ( at( 3, 1 ), mpm::node_free );  // y = 1 > 0.5
    EXPECT_EQ( at( 4, 0 ), mpm::node_fixed ); // on the line at the end
}

} // namespace
