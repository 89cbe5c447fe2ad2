#include <case/mpm_geometry.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_wall_nodes.hpp>

#include <mpm_status_flags.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

/*!
  \brief Reorders `points` cell column by cell column (the cells' x-major
  order, that of the nodes' flat index i * (ny + 1) + j), keeping the order
  within a cell. The step's point loops split the points between threads
  and its node loops split the nodes: in the same order, a thread's share
  of the grid sums and nodal velocities is mostly the one its points
  touched, and stays in its cache.
*/
void orderByCellColumn( InitialPoints& points, const GridConfig& grid )
{
    const double h = grid.cell_size_m;
    const int n_points = points.size();
    std::vector<long> key( n_points );
    for ( int p = 0; p < n_points; ++p )
    {
        const long ci = static_cast<long>(
            std::floor( ( points.x[2 * p] - grid.origin_m[0] ) / h ) );
        const long cj = static_cast<long>(
            std::floor( ( points.x[2 * p + 1] - grid.origin_m[1] ) / h ) );
        key[p] = ci * grid.cells[1] + cj;
    }
    std::vector<int> order( n_points );
    for ( int p = 0; p < n_points; ++p )
        order[p] = p;
    std::stable_sort( order.begin(), order.end(),
                      [&]( const int a, const int b )
                      { return key[a] < key[b]; } );
    InitialPoints sorted;
    sorted.x.reserve( points.x.size() );
    sorted.vol.reserve( points.vol.size() );
    sorted.material.reserve( points.material.size() );
    sorted.body.reserve( points.body.size() );
    for ( const int p : order )
    {
        sorted.x.push_back( points.x[2 * p] );
        sorted.x.push_back( points.x[2 * p + 1] );
        sorted.vol.push_back( points.vol[p] );
        sorted.material.push_back( points.material[p] );
        sorted.body.push_back( points.body[p] );
    }
    points = std::move( sorted );
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
    const std::size_t n_bodies = config.bodies.size();
    // The column of cells of x, within [-1, cells[0]].
    auto column = [&]( const double x )
    {
        const double c = std::floor( ( x - grid.origin_m[0] ) / h );
        return static_cast<int>(
            std::max( -1.0, std::min<double>( c, grid.cells[0] ) ) );
    };

    // Row by row of points (one y), where each body's edges cross the row
    // (geometry::rowCrossings: the crossings of geometry::pointInPolygon).
    // A point is inside a body if an odd number of them lie right of it,
    // between crossings 2k and 2k + 1: only the cells between those (and
    // one on each side, for rounding) are visited, and a point costs a
    // binary search per body. Points and owners are those of testing every
    // point of the grid against every body in turn, in a time that grows
    // with the rows x edges and the points, not the cells; the rows' order
    // is then made the columns' (orderByCellColumn).
    std::vector<std::vector<double>> crossings( n * n_bodies );
    std::vector<double> ys( n );            // the y of the n rows of points
    std::vector<std::pair<int, int>> spans; // cells that may hold points
    InitialPoints points;
    for ( int cj = 0; cj < grid.cells[1]; ++cj )
    {
        spans.clear();
        for ( int b = 0; b < n; ++b )
        {
            ys[b] = grid.origin_m[1] + ( cj + xi[b] ) * h;
            for ( std::size_t k = 0; k < n_bodies; ++k )
            {
                std::vector<double>& row = crossings[b * n_bodies + k];
                geometry::rowCrossings( config.bodies[k].polygon_m, ys[b],
                                        row );
                for ( std::size_t i = 0; i + 1 < row.size(); i += 2 )
                    spans.emplace_back( std::max( 0, column( row[i] ) - 1 ),
                                        std::min( grid.cells[0] - 1,
                                                  column( row[i + 1] ) + 1 ) );
            }
        }
        std::sort( spans.begin(), spans.end() );
        int next = 0; // the first cell not yet visited in this row
        for ( const auto& [span_begin, span_last] : spans )
            for ( int ci = std::max( span_begin, next ); ci <= span_last;
                  next = ++ci )
                for ( int b = 0; b < n; ++b )
                    for ( int a = 0; a < n; ++a )
                    {
                        const Point2 p = {
                            grid.origin_m[0] + ( ci + xi[a] ) * h, ys[b] };
                        for ( std::size_t body_id = 0; body_id < n_bodies;
                              ++body_id )
                        {
                            const std::vector<double>& row =
                                crossings[b * n_bodies + body_id];
                            const auto right =
                                row.end() - std::upper_bound( row.begin(),
                                                              row.end(), p[0] );
                            if ( right % 2 == 0 )
                                continue;
                            const BodyConfig& body = config.bodies[body_id];
                            points.x.push_back( p[0] );
                            points.x.push_back( p[1] );
                            points.vol.push_back( vol );
                            points.material.push_back( body.material_id );
                            points.body.push_back(
                                static_cast<int>( body_id ) );
                            break;
                        }
                    }
    }
    orderByCellColumn( points, grid );
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
                const auto belowPolyline = [&]()
                {
                    const double x = grid.origin_m[0] + i * h;
                    const double y = grid.origin_m[1] + j * h;
                    return y <=
                           geometry::polylineY( bc.polyline_m, x ) + tolerance;
                };
                using B = BoundarySelector;
                const bool selected = bc.where == B::Left     ? i == 0
                                      : bc.where == B::Right  ? i == nx1 - 1
                                      : bc.where == B::Bottom ? j == 0
                                      : bc.where == B::Top    ? j == ny1 - 1
                                      : bc.where == B::Polyline
                                          ? wall[i * ny1 + j] != 0
                                          : belowPolyline();
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
