#include <setup/mpm_geometry.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_wall_nodes.hpp>

#include <mpm_status_flags.hpp>

#include <cmath>

namespace mpm
{
namespace
{
//! Gauss–Legendre abscissae on [0, 1] for n points.
std::vector<double> gaussPositions( const int n )
{
    switch ( n )
    {
    case 1:
        return { 0.5 };
    case 2:
        return { 0.5 - 0.5 / std::sqrt( 3.0 ), 0.5 + 0.5 / std::sqrt( 3.0 ) };
    case 3:
        return { 0.5 - 0.5 * std::sqrt( 0.6 ), 0.5,
                 0.5 + 0.5 * std::sqrt( 0.6 ) };
    default:
    {
        // Beyond 3 points per direction, use equally spaced cell centres.
        std::vector<double> xi( n );
        for ( int k = 0; k < n; ++k )
            xi[k] = ( k + 0.5 ) / n;
        return xi;
    }
    }
}

int flagOf( const BoundaryCondition condition )
{
    switch ( condition )
    {
    case BoundaryCondition::FixX:
        return node_fix_x;
    case BoundaryCondition::FixY:
        return node_fix_y;
    case BoundaryCondition::Fixed:
        break;
    }
    return node_fixed;
}
} // namespace

//---------------------------------------------------------------------------//
InitialPoints generatePoints( const CaseConfig& config )
{
    const GridConfig& grid = config.grid;
    const int n = config.points_per_cell_per_direction;
    const double h = grid.cell_size_m;
    const double vol = h * h / ( n * n );
    const std::vector<double> xi = gaussPositions( n );

    InitialPoints points;
    for ( int cj = 0; cj < grid.cells[1]; ++cj )
        for ( int ci = 0; ci < grid.cells[0]; ++ci )
            for ( int b = 0; b < n; ++b )
                for ( int a = 0; a < n; ++a )
                {
                    const Point2 p = { grid.origin_m[0] + ( ci + xi[a] ) * h,
                                       grid.origin_m[1] + ( cj + xi[b] ) * h };
                    for ( std::size_t body_id = 0;
                          body_id < config.bodies.size(); ++body_id )
                    {
                        const BodyConfig& body = config.bodies[body_id];
                        if ( !geometry::pointInPolygon( body.polygon_m, p ) )
                            continue;
                        points.x.push_back( p[0] );
                        points.x.push_back( p[1] );
                        points.vol.push_back( vol );
                        points.material.push_back( body.material_id );
                        points.body.push_back( static_cast<int>( body_id ) );
                        break;
                    }
                }
    return points;
}

//---------------------------------------------------------------------------//
std::vector<int> nodeFlags( const GridConfig& grid,
                            const std::vector<BoundaryConfig>& boundaries )
{
    const int nx1 = grid.cells[0] + 1;
    const int ny1 = grid.cells[1] + 1;
    const double h = grid.cell_size_m;
    // Nodes within this distance of a polyline count as on it.
    const double tolerance = 1.0e-9 * h;
    std::vector<int> flags( nx1 * ny1, node_free );
    for ( const BoundaryConfig& bc : boundaries )
    {
        if ( !bc.constrains_solid )
            continue;
        const int flag = flagOf( bc.condition );
        const std::vector<int> wall = bc.where == BoundarySelector::Polyline
                                          ? wallNodes( grid, bc.polyline_m )
                                          : std::vector<int>();
        for ( int i = 0; i < nx1; ++i )
            for ( int j = 0; j < ny1; ++j )
            {
                bool selected = false;
                switch ( bc.where )
                {
                case BoundarySelector::Left:
                    selected = i == 0;
                    break;
                case BoundarySelector::Right:
                    selected = i == nx1 - 1;
                    break;
                case BoundarySelector::Bottom:
                    selected = j == 0;
                    break;
                case BoundarySelector::Top:
                    selected = j == ny1 - 1;
                    break;
                case BoundarySelector::BelowPolyline:
                {
                    const double x = grid.origin_m[0] + i * h;
                    const double y = grid.origin_m[1] + j * h;
                    selected = y <= geometry::polylineY( bc.polyline_m, x ) +
                                        tolerance;
                    break;
                }
                case BoundarySelector::Polyline:
                    selected = wall[i * ny1 + j] != 0;
                    break;
                }
                if ( selected )
                    flags[i * ny1 + j] |= flag;
            }
    }
    return flags;
}

//---------------------------------------------------------------------------//
std::vector<BoundaryConfig>
interiorWalls( const std::vector<BoundaryConfig>& boundaries, const bool walls )
{
    std::vector<BoundaryConfig> result;
    for ( const BoundaryConfig& bc : boundaries )
        if ( ( bc.where == BoundarySelector::Polyline ) == walls )
            result.push_back( bc );
    return result;
}

} // namespace mpm
