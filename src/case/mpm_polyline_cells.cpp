#include <case/mpm_polyline_cells.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace mpm
{
namespace
{
//! Flat index of cell (i, j), -1 outside the grid.
int flatCell( const int i, const int j, const GridConfig& grid )
{
    if ( i < 0 || j < 0 || i >= grid.cells[0] || j >= grid.cells[1] )
        return -1;
    return i * grid.cells[1] + j;
}

//! The cell(s) of a piece of line whose midpoint is m: the cell holding
//! it, or the two cells on either side of the grid line it runs along.
std::array<int, 2> pieceCells( const Point2& m, const GridConfig& grid )
{
    // Closer than this (in cells) to a grid line, a piece runs along it:
    // pieces end on grid lines, so only a piece parallel to a grid line
    // has its midpoint there.
    const double on_line = 1.0e-9;
    const double u = ( m[0] - grid.origin_m[0] ) / grid.cell_size_m;
    const double v = ( m[1] - grid.origin_m[1] ) / grid.cell_size_m;
    const int i = static_cast<int>( std::floor( u ) );
    const int j = static_cast<int>( std::floor( v ) );
    const double line_u = std::round( u ), line_v = std::round( v );
    if ( std::abs( v - line_v ) <= on_line )
    {
        const int above = static_cast<int>( line_v );
        return { flatCell( i, above - 1, grid ), flatCell( i, above, grid ) };
    }
    if ( std::abs( u - line_u ) <= on_line )
    {
        const int right = static_cast<int>( line_u );
        return { flatCell( right - 1, j, grid ), flatCell( right, j, grid ) };
    }
    return { flatCell( i, j, grid ), -1 };
}

} // namespace

//---------------------------------------------------------------------------//
double polylineLength( const std::vector<Point2>& line,
                       const LineMeasure measure )
{
    double length = 0.0;
    for ( std::size_t k = 1; k < line.size(); ++k )
    {
        const double dx = line[k][0] - line[k - 1][0];
        const double dy = line[k][1] - line[k - 1][1];
        length += measure == LineMeasure::Horizontal ? std::abs( dx )
                                                     : std::hypot( dx, dy );
    }
    return length;
}

//---------------------------------------------------------------------------//
int cellIndexAt( const double x, const double y, const GridConfig& grid )
{
    const double h = grid.cell_size_m;
    return flatCell(
        static_cast<int>( std::floor( ( x - grid.origin_m[0] ) / h ) ),
        static_cast<int>( std::floor( ( y - grid.origin_m[1] ) / h ) ), grid );
}

//---------------------------------------------------------------------------//
std::vector<PolylinePiece> polylinePieces( const std::vector<Point2>& line,
                                           const GridConfig& grid,
                                           const LineMeasure measure )
{
    std::vector<PolylinePiece> pieces;
    const double h = grid.cell_size_m;
    for ( std::size_t k = 1; k < line.size(); ++k )
    {
        const Point2& a = line[k - 1];
        const Point2& b = line[k];
        const double delta[2] = { b[0] - a[0], b[1] - a[1] };
        const double length = measure == LineMeasure::Horizontal
                                  ? std::abs( delta[0] )
                                  : std::hypot( delta[0], delta[1] );
        if ( !( std::hypot( delta[0], delta[1] ) > 0.0 ) )
            continue;
        // Where the segment crosses the grid lines, as fractions of it
        // (those outside the grid do not matter: no cell lies there).
        std::vector<double> crossings = { 0.0, 1.0 };
        for ( int d = 0; d < 2; ++d )
        {
            if ( delta[d] == 0.0 )
                continue;
            const double lo = ( std::min( a[d], b[d] ) - grid.origin_m[d] ) / h;
            const double hi = ( std::max( a[d], b[d] ) - grid.origin_m[d] ) / h;
            const double first = std::max( std::ceil( lo ), 0.0 );
            const double last =
                std::min( std::floor( hi ), double( grid.cells[d] ) );
            for ( double g = first; g <= last; g += 1.0 )
            {
                const double t = ( grid.origin_m[d] + g * h - a[d] ) / delta[d];
                if ( t > 0.0 && t < 1.0 )
                    crossings.push_back( t );
            }
        }
        std::sort( crossings.begin(), crossings.end() );
        for ( std::size_t c = 1; c < crossings.size(); ++c )
        {
            const double t0 = crossings[c - 1], t1 = crossings[c];
            if ( !( t1 - t0 > 1.0e-14 ) )
                continue;
            const double t = 0.5 * ( t0 + t1 );
            PolylinePiece piece;
            piece.cells = pieceCells(
                { a[0] + t * delta[0], a[1] + t * delta[1] }, grid );
            piece.length_m = length * ( t1 - t0 );
            pieces.push_back( piece );
        }
    }
    return pieces;
}

//---------------------------------------------------------------------------//
std::map<int, double>
polylineCellShares( const std::vector<PolylinePiece>& pieces,
                    const std::set<int>& occupied )
{
    std::map<int, double> shares;
    double fed_length = 0.0;
    for ( const PolylinePiece& piece : pieces )
    {
        int fed[2], count = 0;
        for ( const int cell : piece.cells )
            if ( cell >= 0 && occupied.count( cell ) )
                fed[count++] = cell;
        for ( int k = 0; k < count; ++k )
            shares[fed[k]] += piece.length_m / count;
        if ( count > 0 )
            fed_length += piece.length_m;
    }
    if ( !( fed_length > 0.0 ) )
        return {};
    // A cell the line crosses only vertically has no horizontal length.
    for ( auto it = shares.begin(); it != shares.end(); )
        it = it->second > 0.0 ? std::next( it ) : shares.erase( it );
    for ( auto& share : shares )
        share.second /= fed_length;
    return shares;
}

} // namespace mpm
