// Point selections of stage conditions: `surface_points`, the two highest
// points of each column of points (setup/mpm_conditions).
#include <setup/mpm_conditions.hpp>

#include <mpm_status_flags.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace
{
//---------------------------------------------------------------------------//
// A stepped surface of points 0.5 m apart (2 per 1 m cell), column k holding
// 2 + k points, each moved by up to 1 mm (as after a first stage); the top
// point of the last column is removed, so the two below it are picked.
TEST( PointSelection, surface_points_are_the_two_highest_of_each_column )
{
    std::vector<double> x;
    std::vector<int> status;
    std::vector<bool> expected;
    const int columns = 6;
    for ( int k = 0; k < columns; ++k )
    {
        const int n = 2 + k;
        for ( int j = 0; j < n; ++j )
        {
            const double jitter = 1.0e-3 * ( ( j + k ) % 3 - 1 );
            x.push_back( 0.25 + 0.5 * k + jitter );
            x.push_back( 0.25 + 0.5 * j - jitter );
            const bool removed = k == columns - 1 && j == n - 1;
            status.push_back( removed ? mpm::point_removed
                                      : mpm::point_active );
            const int top = k == columns - 1 ? n - 2 : n - 1;
            expected.push_back( !removed && j >= top - 1 );
        }
    }
    mpm::PointSelection selection;
    selection.kind = mpm::PointSelection::Kind::SurfacePoints;
    mpm::GridConfig grid;
    grid.cell_size_m = 1.0;
    grid.cells = { 4, 6 };
    EXPECT_EQ( mpm::selectPoints( selection, x, status, grid ), expected );
}

} // namespace
