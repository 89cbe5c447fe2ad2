#include <case/mpm_geometry.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace mpm
{
namespace geometry
{
namespace
{
//---------------------------------------------------------------------------//
// Number of vertices without a repeated closing vertex.
std::size_t vertexCount( const std::vector<Point2>& polygon )
{
    std::size_t n = polygon.size();
    if ( n > 1 && polygon.front() == polygon.back() )
        --n;
    return n;
}

//---------------------------------------------------------------------------//
// Twice the signed area of triangle (a, b, c): > 0 if counter-clockwise.
double cross( const Point2& a, const Point2& b, const Point2& c )
{
    return ( b[0] - a[0] ) * ( c[1] - a[1] ) -
           ( b[1] - a[1] ) * ( c[0] - a[0] );
}

//---------------------------------------------------------------------------//
int orientation( const Point2& a, const Point2& b, const Point2& c )
{
    const double d = cross( a, b, c );
    return ( d > 0.0 ) - ( d < 0.0 );
}

//---------------------------------------------------------------------------//
// Whether c, known to be collinear with segment ab, lies on that segment.
bool onSegment( const Point2& a, const Point2& b, const Point2& c )
{
    return std::min( a[0], b[0] ) <= c[0] && c[0] <= std::max( a[0], b[0] ) &&
           std::min( a[1], b[1] ) <= c[1] && c[1] <= std::max( a[1], b[1] );
}

//---------------------------------------------------------------------------//
// Whether closed segments pq and rs share at least one point.
bool segmentsIntersect( const Point2& p, const Point2& q, const Point2& r,
                        const Point2& s )
{
    const int o1 = orientation( p, q, r );
    const int o2 = orientation( p, q, s );
    const int o3 = orientation( r, s, p );
    const int o4 = orientation( r, s, q );
    // Proper crossing, or an endpoint of one segment on the other.
    if ( o1 != o2 && o3 != o4 )
        return true;
    return ( o1 == 0 && onSegment( p, q, r ) ) ||
           ( o2 == 0 && onSegment( p, q, s ) ) ||
           ( o3 == 0 && onSegment( r, s, p ) ) ||
           ( o4 == 0 && onSegment( r, s, q ) );
}

//---------------------------------------------------------------------------//
// Adjacent edges a -> b and b -> c overlap if they are collinear and c turns
// back along a -> b, or if either has zero length.
bool adjacentEdgesOverlap( const Point2& a, const Point2& b, const Point2& c )
{
    if ( a == b || b == c )
        return true;
    if ( orientation( a, b, c ) != 0 )
        return false;
    const double dot =
        ( b[0] - a[0] ) * ( c[0] - b[0] ) + ( b[1] - a[1] ) * ( c[1] - b[1] );
    return dot < 0.0;
}

//---------------------------------------------------------------------------//
// Whether edge ab crosses the line at height y (half-open in y: one of its
// ends above y, the other not) and where (x_cross). pointInPolygon and
// rowCrossings share it, so they find the same crossings to the last bit.
bool edgeCrossing( const Point2& a, const Point2& b, const double y,
                   double& x_cross )
{
    if ( ( a[1] > y ) == ( b[1] > y ) )
        return false;
    x_cross = a[0] + ( y - a[1] ) * ( b[0] - a[0] ) / ( b[1] - a[1] );
    return true;
}

} // namespace

//---------------------------------------------------------------------------//
bool pointInPolygon( const std::vector<Point2>& polygon, const Point2& p )
{
    const std::size_t n = vertexCount( polygon );
    if ( n < 3 )
        return false;

    // Count crossings of the ray from p towards +x (half-open in y).
    bool inside = false;
    for ( std::size_t i = 0, j = n - 1; i < n; j = i++ )
    {
        double x_cross = 0.0;
        if ( edgeCrossing( polygon[i], polygon[j], p[1], x_cross ) &&
             p[0] < x_cross )
            inside = !inside;
    }
    return inside;
}

//---------------------------------------------------------------------------//
void rowCrossings( const std::vector<Point2>& polygon, const double y,
                   std::vector<double>& crossings )
{
    crossings.clear();
    const std::size_t n = vertexCount( polygon );
    if ( n < 3 )
        return;
    for ( std::size_t i = 0, j = n - 1; i < n; j = i++ )
    {
        double x_cross = 0.0;
        if ( edgeCrossing( polygon[i], polygon[j], y, x_cross ) )
            crossings.push_back( x_cross );
    }
    std::sort( crossings.begin(), crossings.end() );
}

//---------------------------------------------------------------------------//
double polygonArea( const std::vector<Point2>& polygon )
{
    const std::size_t n = vertexCount( polygon );
    if ( n < 3 )
        return 0.0;

    // Shoelace formula.
    double twice_area = 0.0;
    for ( std::size_t i = 0, j = n - 1; i < n; j = i++ )
        twice_area +=
            polygon[j][0] * polygon[i][1] - polygon[i][0] * polygon[j][1];
    return 0.5 * std::abs( twice_area );
}

//---------------------------------------------------------------------------//
bool findSelfIntersection( const std::vector<Point2>& polygon, int& edge_a,
                           int& edge_b )
{
    const std::size_t n = vertexCount( polygon );
    if ( n < 3 )
        return false;
    auto vertex = [&]( const std::size_t k ) -> const Point2&
    { return polygon[k % n]; };

    for ( std::size_t a = 0; a < n; ++a )
    {
        for ( std::size_t b = a + 1; b < n; ++b )
        {
            bool hit = false;
            if ( b == a + 1 )
                hit = adjacentEdgesOverlap( vertex( a ), vertex( b ),
                                            vertex( b + 1 ) );
            else if ( a == 0 && b == n - 1 )
                hit = adjacentEdgesOverlap( vertex( b ), vertex( 0 ),
                                            vertex( 1 ) );
            else
                hit = segmentsIntersect( vertex( a ), vertex( a + 1 ),
                                         vertex( b ), vertex( b + 1 ) );
            if ( hit )
            {
                edge_a = static_cast<int>( a );
                edge_b = static_cast<int>( b );
                return true;
            }
        }
    }
    return false;
}

//---------------------------------------------------------------------------//
double polylineY( const std::vector<Point2>& polyline, const double x )
{
    if ( polyline.empty() )
        throw std::invalid_argument(
            "mpm::geometry::polylineY: empty polyline" );
    if ( x <= polyline.front()[0] )
        return polyline.front()[1];
    if ( x >= polyline.back()[0] )
        return polyline.back()[1];

    // First vertex with x_k > x; the segment is [k - 1, k].
    const auto it = std::upper_bound( polyline.begin(), polyline.end(), x,
                                      []( const double value, const Point2& v )
                                      { return value < v[0]; } );
    const Point2& b = *it;
    const Point2& a = *( it - 1 );
    const double t = ( x - a[0] ) / ( b[0] - a[0] );
    return a[1] + t * ( b[1] - a[1] );
}

//---------------------------------------------------------------------------//
bool segmentMeetsOpenSquare( const Point2& a, const Point2& b, const Point2& c,
                             const double r )
{
    // The parameters t of a + t (b - a) inside the square form the open
    // interval (t_lo, t_hi) (Liang–Barsky); it must meet [0, 1].
    double t_lo = -1.0e300, t_hi = 1.0e300;
    for ( int d = 0; d < 2; ++d )
    {
        const double step = b[d] - a[d];
        const double lo = c[d] - r - a[d], hi = c[d] + r - a[d];
        if ( step == 0.0 )
        {
            if ( !( lo < 0.0 && 0.0 < hi ) )
                return false;
            continue;
        }
        const double t0 = lo / step, t1 = hi / step;
        t_lo = std::max( t_lo, std::min( t0, t1 ) );
        t_hi = std::min( t_hi, std::max( t0, t1 ) );
    }
    return t_lo < t_hi && t_lo < 1.0 && t_hi > 0.0;
}

} // namespace geometry
} // namespace mpm
