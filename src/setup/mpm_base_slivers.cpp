#include <setup/mpm_base_slivers.hpp>

#include <mpm_device_type.hpp>

#include <cmath>

namespace mpm
{
int fixBaseSlivers( const GridConfig& grid, const std::vector<double>& x,
                    std::vector<int>& flags, std::vector<int>* water_flags )
{
    const int nx = grid.cells[0];
    const int ny = grid.cells[1];
    const int ny1 = ny + 1;
    const double h = grid.cell_size_m;
    std::vector<int> points( static_cast<std::size_t>( nx ) * ny, 0 );
    for ( std::size_t p = 0; p + 1 < x.size(); p += 2 )
    {
        const int ci =
            static_cast<int>( std::floor( ( x[p] - grid.origin_m[0] ) / h ) );
        const int cj = static_cast<int>(
            std::floor( ( x[p + 1] - grid.origin_m[1] ) / h ) );
        if ( ci >= 0 && ci < nx && cj >= 0 && cj < ny )
            ++points[ci * ny + cj];
    }
    const auto node = [&]( const int ci, const int cj, const int k )
    { return ( ci + ( k & 1 ) ) * ny1 + cj + ( k >> 1 ); };
    const auto fixed = [&]( const int n )
    { return ( flags[n] & node_fixed ) == node_fixed; };
    int num_fixed = 0;
    for ( bool changed = true; changed; )
    {
        changed = false;
        for ( int ci = 0; ci < nx; ++ci )
            for ( int cj = 0; cj < ny; ++cj )
            {
                if ( points[ci * ny + cj] > 0 )
                    continue;
                int water = 0, num_fixed_nodes = 0;
                for ( int k = 0; k < 4; ++k )
                    if ( fixed( node( ci, cj, k ) ) )
                    {
                        ++num_fixed_nodes;
                        if ( water_flags )
                            water |= ( *water_flags )[node( ci, cj, k )];
                    }
                if ( num_fixed_nodes == 0 || num_fixed_nodes == 4 )
                    continue;
                for ( int k = 0; k < 4; ++k )
                {
                    const int n = node( ci, cj, k );
                    if ( fixed( n ) )
                        continue;
                    flags[n] |= node_fixed;
                    if ( water_flags )
                        ( *water_flags )[n] |= water;
                    ++num_fixed;
                    changed = true;
                }
            }
    }
    return num_fixed;
}

} // namespace mpm
