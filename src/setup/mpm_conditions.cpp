#include <case/mpm_geometry.hpp>
#include <case/mpm_polyline_cells.hpp>
#include <setup/mpm_conditions.hpp>
#include <setup/mpm_particle_generator.hpp>

#include <mpm_status_flags.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace mpm
{
//---------------------------------------------------------------------------//
double
interpolatePiecewiseLinear( const std::vector<std::array<double, 2>>& table,
                            const double x )
{
    if ( x <= table.front()[0] )
        return table.front()[1];
    for ( std::size_t k = 1; k < table.size(); ++k )
        if ( x <= table[k][0] )
        {
            const auto& a = table[k - 1];
            const auto& b = table[k];
            return a[1] + ( b[1] - a[1] ) * ( x - a[0] ) / ( b[0] - a[0] );
        }
    return table.back()[1];
}

//---------------------------------------------------------------------------//
double evaluateTimeFunction( const TimeFunction& function, const double t )
{
    return function.empty() ? 1.0 : interpolatePiecewiseLinear( function, t );
}

//---------------------------------------------------------------------------//
double meanOfTimeFunction( const TimeFunction& function, const double t0,
                           const double t1 )
{
    if ( function.empty() || !( t1 > t0 ) )
        return evaluateTimeFunction( function, t1 );
    // f is linear between t0, the pairs' times inside (t0, t1) and t1.
    double integral = 0.0, t = t0, f = evaluateTimeFunction( function, t0 );
    for ( const auto& pair : function )
        if ( pair[0] > t0 && pair[0] < t1 )
        {
            integral += 0.5 * ( f + pair[1] ) * ( pair[0] - t );
            t = pair[0];
            f = pair[1];
        }
    integral += 0.5 * ( f + evaluateTimeFunction( function, t1 ) ) * ( t1 - t );
    return integral / ( t1 - t0 );
}

//---------------------------------------------------------------------------//
double initialPorePressure( const BodyConfig& body, const double y )
{
    if ( !body.initial_pore_pressure_profile.empty() )
        return interpolatePiecewiseLinear( body.initial_pore_pressure_profile,
                                           y );
    return body.initial_pore_pressure_pa +
           body.initial_pore_pressure_gradient_pa_per_m * y;
}

//---------------------------------------------------------------------------//
std::map<int, double> polylineSelectionShares( const PointSelection& selection,
                                               const std::vector<double>& x,
                                               const std::vector<int>& status,
                                               const GridConfig& grid )
{
    std::set<int> occupied;
    for ( std::size_t p = 0; p < status.size(); ++p )
        if ( status[p] == point_active )
        {
            const int cell = cellIndexAt( x[2 * p], x[2 * p + 1], grid );
            if ( cell >= 0 )
                occupied.insert( cell );
        }
    return polylineCellShares( polylinePieces( selection.polyline_m, grid,
                                               selection.polyline_measure ),
                               occupied );
}

//---------------------------------------------------------------------------//
namespace
{
// Whether cell (i, j) lies along the grid edge of an edge-cells selection.
bool inEdgeCells( const PointSelection::Kind kind,
                  const std::pair<int, int>& cell, const GridConfig& grid )
{
    switch ( kind )
    {
    case PointSelection::Kind::TopCells:
        return cell.second >= grid.cells[1] - 1;
    case PointSelection::Kind::BottomCells:
        return cell.second <= 0;
    case PointSelection::Kind::LeftCells:
        return cell.first <= 0;
    case PointSelection::Kind::RightCells:
        return cell.first >= grid.cells[0] - 1;
    default:
        return false;
    }
}
} // namespace

//---------------------------------------------------------------------------//
std::vector<bool> topPointsOfColumns( const std::vector<double>& x,
                                      const std::vector<int>& status,
                                      const double cell_size_m,
                                      const std::size_t count )
{
    std::vector<std::size_t> order;
    for ( std::size_t p = 0; p < status.size(); ++p )
        if ( status[p] == point_active )
            order.push_back( p );
    std::sort( order.begin(), order.end(),
               [&]( std::size_t a, std::size_t b )
               { return x[2 * a] < x[2 * b]; } );
    std::vector<bool> picked( status.size(), false );
    std::size_t begin = 0;
    while ( begin < order.size() )
    {
        std::size_t end = begin + 1;
        while ( end < order.size() &&
                x[2 * order[end]] - x[2 * order[end - 1]] <= 0.1 * cell_size_m )
            ++end;
        std::sort( order.begin() + begin, order.begin() + end,
                   [&]( std::size_t a, std::size_t b )
                   { return x[2 * a + 1] > x[2 * b + 1]; } );
        for ( std::size_t k = begin; k < std::min( end, begin + count ); ++k )
            picked[order[k]] = true;
        begin = end;
    }
    return picked;
}

//---------------------------------------------------------------------------//
std::vector<bool> selectPoints( const PointSelection& selection,
                                const std::vector<double>& x,
                                const std::vector<int>& status,
                                const GridConfig& grid )
{
    const std::size_t n = status.size();
    std::vector<bool> picked( n, false );
    const double h = grid.cell_size_m;
    auto cellOf = [&]( std::size_t p )
    {
        return std::make_pair(
            static_cast<int>(
                std::floor( ( x[2 * p] - grid.origin_m[0] ) / h ) ),
            static_cast<int>(
                std::floor( ( x[2 * p + 1] - grid.origin_m[1] ) / h ) ) );
    };
    std::set<std::pair<int, int>> occupied;
    if ( selection.kind == PointSelection::Kind::SurfaceCells )
        for ( std::size_t p = 0; p < n; ++p )
            if ( status[p] == point_active )
                occupied.insert( cellOf( p ) );
    if ( selection.kind == PointSelection::Kind::SurfacePoints )
        return topPointsOfColumns( x, status, grid.cell_size_m, 2 );
    std::map<int, double> shares;
    if ( selection.kind == PointSelection::Kind::Polyline )
        shares = polylineSelectionShares( selection, x, status, grid );

    for ( std::size_t p = 0; p < n; ++p )
    {
        if ( status[p] != point_active )
            continue;
        if ( selection.kind == PointSelection::Kind::Box )
        {
            const auto& b = selection.box_m;
            picked[p] = x[2 * p] >= b[0][0] && x[2 * p] <= b[1][0] &&
                        x[2 * p + 1] >= b[0][1] && x[2 * p + 1] <= b[1][1];
        }
        else if ( selection.kind == PointSelection::Kind::SurfaceCells )
        {
            const auto cell = cellOf( p );
            picked[p] = occupied.count( { cell.first, cell.second + 1 } ) == 0;
        }
        else if ( selection.kind == PointSelection::Kind::All )
            picked[p] = true;
        else if ( selection.kind == PointSelection::Kind::Polyline )
            picked[p] =
                shares.count( cellIndexAt( x[2 * p], x[2 * p + 1], grid ) ) > 0;
        else
            picked[p] = inEdgeCells( selection.kind, cellOf( p ), grid );
    }
    return picked;
}

//---------------------------------------------------------------------------//
double horizontalExtent( const std::vector<bool>& picked,
                         const std::vector<double>& x, const GridConfig& grid )
{
    std::set<int> columns;
    for ( std::size_t p = 0; p < picked.size(); ++p )
        if ( picked[p] )
            columns.insert( static_cast<int>( std::floor(
                ( x[2 * p] - grid.origin_m[0] ) / grid.cell_size_m ) ) );
    return static_cast<double>( columns.size() ) * grid.cell_size_m;
}

//---------------------------------------------------------------------------//
std::vector<int> waterNodeFlags( const GridConfig& grid,
                                 const std::vector<BoundaryConfig>& boundaries )
{
    const int nx1 = grid.cells[0] + 1;
    const int ny1 = grid.cells[1] + 1;
    std::vector<int> flags( nx1 * ny1, node_free );
    // Grid edges are impermeable by default.
    for ( int i = 0; i < nx1; ++i )
        for ( int j = 0; j < ny1; ++j )
        {
            if ( i == 0 || i == nx1 - 1 )
                flags[i * ny1 + j] |= node_fix_x;
            if ( j == 0 || j == ny1 - 1 )
                flags[i * ny1 + j] |= node_fix_y;
        }
    for ( const BoundaryConfig& bc : boundaries )
    {
        // A drained wall lets the water through: it changes no tie (clearing
        // them would open a drain where it meets an impermeable grid edge).
        if ( bc.where == BoundarySelector::Polyline &&
             bc.hydraulic == HydraulicCondition::Drained )
            continue;
        // Reuse the solid selector: the nodes a fixed condition would pick.
        BoundaryConfig selector = bc;
        selector.condition = BoundaryCondition::Fixed;
        selector.constrains_solid = true;
        const std::vector<int> selected = nodeFlags( grid, { selector } );
        int tie = node_fixed;
        if ( bc.where == BoundarySelector::Left ||
             bc.where == BoundarySelector::Right )
            tie = node_fix_x;
        else if ( bc.where == BoundarySelector::Bottom ||
                  bc.where == BoundarySelector::Top )
            tie = node_fix_y;
        for ( std::size_t k = 0; k < flags.size(); ++k )
        {
            if ( selected[k] == node_free )
                continue;
            if ( bc.hydraulic == HydraulicCondition::Drained )
                flags[k] &= ~tie;
            else
                flags[k] |= tie;
        }
    }
    return flags;
}

} // namespace mpm
