#include <case/mpm_geometry.hpp>
#include <setup/mpm_wall_nodes.hpp>

#include <algorithm>
#include <cmath>

namespace mpm
{
std::vector<int> wallNodes( const GridConfig& grid,
                            const std::vector<Point2>& polyline )
{
    const int nx1 = grid.cells[0] + 1;
    const int ny1 = grid.cells[1] + 1;
    const double h = grid.cell_size_m;
    // The half-width of a node's support, less round-off: a wall on the
    // next grid line (distance h up to round-off) does not select it.
    const double reach = h * ( 1.0 - 1.0e-9 );
    std::vector<int> selected( static_cast<std::size_t>( nx1 ) * ny1, 0 );
    // Node index range [lo, hi] whose support may meet [a, b] along axis d.
    auto range = [&]( const double a, const double b, const int d, const int n1,
                      int& lo, int& hi )
    {
        const double s0 = ( std::min( a, b ) - grid.origin_m[d] ) / h;
        const double s1 = ( std::max( a, b ) - grid.origin_m[d] ) / h;
        lo = std::max( 0, static_cast<int>( std::floor( s0 ) ) - 1 );
        hi = std::min( n1 - 1, static_cast<int>( std::ceil( s1 ) ) + 1 );
    };
    // A single vertex is a segment of zero length.
    const std::size_t segments = polyline.size() > 1 ? polyline.size() - 1 : 1;
    for ( std::size_t k = 0; k < segments && !polyline.empty(); ++k )
    {
        const Point2& a = polyline[k];
        const Point2& b = polyline[std::min( k + 1, polyline.size() - 1 )];
        int i0, i1, j0, j1;
        range( a[0], b[0], 0, nx1, i0, i1 );
        range( a[1], b[1], 1, ny1, j0, j1 );
        for ( int i = i0; i <= i1; ++i )
            for ( int j = j0; j <= j1; ++j )
            {
                const Point2 node = { grid.origin_m[0] + i * h,
                                      grid.origin_m[1] + j * h };
                if ( geometry::segmentMeetsOpenSquare( a, b, node, reach ) )
                    selected[static_cast<std::size_t>( i ) * ny1 + j] = 1;
            }
    }
    return selected;
}

} // namespace mpm
