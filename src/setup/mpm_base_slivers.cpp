#include <case/mpm_geometry.hpp>
#include <setup/mpm_base_slivers.hpp>

#include <mpm_device_type.hpp>

#include <algorithm>

namespace mpm
{
int fixBaseSlivers( const physics::GridGeometry& grid,
                    const std::vector<double>& x,
                    const std::vector<int>& cut_cells, std::vector<int>& flags,
                    std::vector<int>* water_flags )
{
    const int nx = grid.nx;
    const int ny = grid.ny;
    const int ny1 = ny + 1;
    std::vector<int> points( static_cast<std::size_t>( nx ) * ny, 0 );
    for ( std::size_t p = 0; p + 1 < x.size(); p += 2 )
    {
        int ci, cj;
        if ( grid.cellOf( x[p], x[p + 1], ci, cj ) )
            ++points[ci * ny + cj];
    }
    const auto node = [&]( const int ci, const int cj, const int k )
    { return ( ci + ( k & 1 ) ) * ny1 + cj + ( k >> 1 ); };
    const auto fixed = [&]( const int n ) { return fullyFixed( flags[n] ); };
    int num_fixed = 0;
    for ( bool changed = true; changed; )
    {
        changed = false;
        for ( int ci = 0; ci < nx; ++ci )
            for ( int cj = 0; cj < ny; ++cj )
            {
                if ( points[ci * ny + cj] > 0 || !cut_cells[ci * ny + cj] )
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

//---------------------------------------------------------------------------//
std::vector<int> cutBaseCells( const GridConfig& grid,
                               const std::vector<BoundaryConfig>& boundaries )
{
    const int nx = grid.cells[0];
    const int ny = grid.cells[1];
    const double h = grid.cell_size_m;
    const double tolerance = 1.0e-9 * h;
    std::vector<int> cut( static_cast<std::size_t>( nx ) * ny, 0 );
    for ( const BoundaryConfig& bc : boundaries )
    {
        if ( bc.where != BoundarySelector::BelowPolyline ||
             !bc.constrains_solid || bc.condition != BoundaryCondition::Fixed )
            continue;
        for ( int ci = 0; ci < nx; ++ci )
        {
            // The line's range of y over the column of cells: at its ends
            // and at the vertices inside it.
            const double x0 = grid.origin_m[0] + ci * h;
            const double x1 = x0 + h;
            double y_lo = std::min( geometry::polylineY( bc.polyline_m, x0 ),
                                    geometry::polylineY( bc.polyline_m, x1 ) );
            double y_hi = std::max( geometry::polylineY( bc.polyline_m, x0 ),
                                    geometry::polylineY( bc.polyline_m, x1 ) );
            for ( const Point2& v : bc.polyline_m )
                if ( v[0] > x0 && v[0] < x1 )
                {
                    y_lo = std::min( y_lo, v[1] );
                    y_hi = std::max( y_hi, v[1] );
                }
            for ( int cj = 0; cj < ny; ++cj )
            {
                const double y0 = grid.origin_m[1] + cj * h;
                const double y1 = y0 + h;
                if ( y_hi > y0 + tolerance && y_lo < y1 - tolerance )
                    cut[ci * ny + cj] = 1;
            }
        }
    }
    return cut;
}

} // namespace mpm
