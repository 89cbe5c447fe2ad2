#include <case/mpm_geometry.hpp>
#include <io/mpm_case_shapes.hpp>
#include <io/mpm_toml_access.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//---------------------------------------------------------------------------//
// "(x, y)" of a point, for messages.
std::string pointText( const Point2& p )
{
    return "(" + formatNumber( p[0] ) + ", " + formatNumber( p[1] ) + ")";
}

// Reports the first of the vertices (the array `arr` at `path`) that lies
// outside the grid.
void checkVerticesInGrid( const toml::array& arr,
                          const std::vector<Point2>& vertices,
                          const std::string& path, const GridConfig& grid,
                          Diagnostics& diag )
{
    for ( std::size_t k = 0; k < vertices.size(); ++k )
    {
        const std::string outside = outsideGridText( grid, vertices[k] );
        if ( outside.empty() )
            continue;
        diag.keyError( *arr.get( k ), indexed( path, k ),
                       "expected a vertex " + outside );
        return;
    }
}

} // namespace

//---------------------------------------------------------------------------//
void checkBodyPolygon( std::vector<Point2>& polygon, const toml::node& node,
                       const std::string& path, const GridConfig* grid,
                       Diagnostics& diag )
{
    const auto& arr = *node.as_array();
    if ( polygon.size() > 1 && polygon.front() == polygon.back() )
        polygon.pop_back(); // a repeated closing vertex is allowed
    const std::size_t n = polygon.size();
    if ( n < 3 )
    {
        diag.mismatch( node, path,
                       "at least 3 distinct vertices [[x, y], ...] in m "
                       "(a repeated closing vertex is ignored)" );
        return;
    }

    // Consecutive vertices must differ.
    for ( std::size_t k = 0; k < n; ++k )
    {
        const std::size_t next = ( k + 1 ) % n;
        if ( polygon[k] == polygon[next] )
        {
            diag.keyError( *arr.get( next ), indexed( path, next ),
                           "vertex " + pointText( polygon[k] ) +
                               " m is repeated; consecutive polygon vertices "
                               "must differ" );
            return;
        }
    }

    // The outline must not cross or touch itself.
    int a = 0, b = 0;
    if ( geometry::findSelfIntersection( polygon, a, b ) )
    {
        auto edge = [&]( const int e )
        {
            return "edge " + std::to_string( e ) + " " +
                   pointText( polygon[e] ) + "-" +
                   pointText( polygon[( e + 1 ) % n] );
        };
        diag.keyError( node, path,
                       "expected a simple polygon, found one that intersects "
                       "itself: " +
                           edge( a ) + " and " + edge( b ) +
                           " m cross or overlap; list the vertices in order "
                           "around the outline of the body" );
        return;
    }

    // Every vertex inside the grid (up to round-off).
    if ( grid )
        checkVerticesInGrid( arr, polygon, path, *grid, diag );
}

//---------------------------------------------------------------------------//
namespace
{
//! Upper end of the grid along direction d, m.
double gridUpper( const GridConfig& g, const int d )
{
    return g.origin_m[d] + g.cells[d] * g.cell_size_m;
}

//! "x in [x0, x1] m and y in [y0, y1] m": the grid's extent.
std::string gridSpanText( const GridConfig& g )
{
    auto span = [&]( const int d )
    {
        return "[" + formatNumber( g.origin_m[d] ) + ", " +
               formatNumber( gridUpper( g, d ) ) + "]";
    };
    return "x in " + span( 0 ) + " m and y in " + span( 1 ) + " m";
}
} // namespace

std::string outsideGridText( const GridConfig& g, const Point2& point )
{
    const double tol = 1e-9 * g.cell_size_m;
    bool inside = true;
    for ( int d = 0; d < 2; ++d )
        inside = inside && point[d] >= g.origin_m[d] - tol &&
                 point[d] <= gridUpper( g, d ) + tol;
    if ( inside )
        return "";
    return "inside the grid, " + gridSpanText( g ) +
           " (grid.origin_m + grid.cells * grid.cell_size_m), found " +
           pointText( point ) + " m";
}

//---------------------------------------------------------------------------//
void warnPolylineOutsideGrid( const std::vector<Point2>& line,
                              const toml::node& node, const std::string& path,
                              const GridConfig& grid,
                              const std::string& consequence,
                              Diagnostics& diag )
{
    std::size_t first = line.size(), outside = 0;
    for ( std::size_t k = 0; k < line.size(); ++k )
        if ( !outsideGridText( grid, line[k] ).empty() )
        {
            first = std::min( first, k );
            ++outside;
        }
    if ( outside == 0 )
        return;
    const auto* arr = node.as_array();
    const toml::node& at =
        arr && first < arr->size() ? *arr->get( first ) : node;
    diag.keyWarning(
        at, indexed( path, first ),
        "the point " + pointText( line[first] ) + " m lies outside the grid (" +
            std::to_string( outside ) + " of the " +
            std::to_string( line.size() ) + " points do; the grid spans " +
            gridSpanText( grid ) + "); " + consequence );
}

//---------------------------------------------------------------------------//
void checkPolyline( const std::vector<Point2>& line, const toml::node& node,
                    const std::string& path, Diagnostics& diag )
{
    for ( std::size_t k = 1; k < line.size(); ++k )
    {
        if ( !( line[k][0] > line[k - 1][0] ) )
        {
            diag.keyError( *node.as_array()->get( k ), indexed( path, k ),
                           "expected x > " + formatNumber( line[k - 1][0] ) +
                               " m (x must increase strictly along the "
                               "polyline), found x = " +
                               formatNumber( line[k][0] ) + " m" );
            return;
        }
    }
}

//---------------------------------------------------------------------------//
void checkWallPolyline( const std::vector<Point2>& line, const toml::node& node,
                        const std::string& path, const GridConfig* grid,
                        Diagnostics& diag )
{
    const auto& arr = *node.as_array();
    for ( std::size_t k = 1; k < line.size(); ++k )
        if ( line[k] == line[k - 1] )
        {
            diag.keyError( *arr.get( k ), indexed( path, k ),
                           "vertex " + pointText( line[k] ) +
                               " m is repeated; consecutive wall vertices "
                               "must differ" );
            return;
        }
    if ( grid )
        checkVerticesInGrid( arr, line, path, *grid, diag );
}

} // namespace Impl
} // namespace mpm
