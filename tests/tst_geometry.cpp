// Polygon and polyline geometry (case/mpm_geometry.hpp): points in
// polygons, areas, self-intersections, polyline interpolation.
#include <case/mpm_geometry.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace
{
using mpm::Point2;
namespace geo = mpm::geometry;

const std::vector<Point2> unit_square = {
    { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 }, { 0.0, 1.0 } };

// L-shape: the 2 x 2 square minus its upper-right quarter (area 3).
const std::vector<Point2> l_shape = { { 0.0, 0.0 }, { 2.0, 0.0 },
                                      { 2.0, 1.0 }, { 1.0, 1.0 },
                                      { 1.0, 2.0 }, { 0.0, 2.0 } };

//---------------------------------------------------------------------------//
// Geometry.
//---------------------------------------------------------------------------//
TEST( Geometry, point_in_square_either_orientation )
{
    std::vector<Point2> clockwise( unit_square.rbegin(), unit_square.rend() );
    for ( const auto& polygon : { unit_square, clockwise } )
    {
        EXPECT_TRUE( geo::pointInPolygon( polygon, { 0.5, 0.5 } ) );
        EXPECT_TRUE( geo::pointInPolygon( polygon, { 0.01, 0.99 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { 1.5, 0.5 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { 0.5, -0.1 } ) );
        EXPECT_FALSE( geo::pointInPolygon( polygon, { -3.0, 0.5 } ) );
    }
}

TEST( Geometry, repeated_closing_vertex_is_ignored )
{
    auto closed = unit_square;
    closed.push_back( closed.front() );
    EXPECT_TRUE( geo::pointInPolygon( closed, { 0.5, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( closed, { 1.5, 0.5 } ) );
    EXPECT_DOUBLE_EQ( geo::polygonArea( closed ), 1.0 );
    int a = -1, b = -1;
    EXPECT_FALSE( geo::findSelfIntersection( closed, a, b ) );
}

TEST( Geometry, concave_l_shape )
{
    EXPECT_TRUE( geo::pointInPolygon( l_shape, { 0.5, 1.5 } ) );
    EXPECT_TRUE( geo::pointInPolygon( l_shape, { 1.5, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( l_shape, { 1.5, 1.5 } ) ); // notch
    EXPECT_DOUBLE_EQ( geo::polygonArea( l_shape ), 3.0 );
    std::vector<Point2> clockwise( l_shape.rbegin(), l_shape.rend() );
    EXPECT_DOUBLE_EQ( geo::polygonArea( clockwise ), 3.0 );
    int a = -1, b = -1;
    EXPECT_FALSE( geo::findSelfIntersection( l_shape, a, b ) );
    EXPECT_FALSE( geo::findSelfIntersection( clockwise, a, b ) );
}

TEST( Geometry, bow_tie_intersects_itself )
{
    const std::vector<Point2> bow_tie = {
        { 0.0, 0.0 }, { 1.0, 1.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } };
    int a = -1, b = -1;
    ASSERT_TRUE( geo::findSelfIntersection( bow_tie, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 2 );
    // Even-odd rule: both lobes are inside, the gap between them is not.
    EXPECT_TRUE( geo::pointInPolygon( bow_tie, { 0.1, 0.5 } ) );
    EXPECT_FALSE( geo::pointInPolygon( bow_tie, { 0.5, 0.9 } ) );
}

TEST( Geometry, touching_and_folding_edges_count_as_intersection )
{
    int a = -1, b = -1;
    // Vertex 3 touches edge 0 (non-adjacent edges touch).
    const std::vector<Point2> touching = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 2.0 }, { 1.0, 0.0 }, { 0.0, 2.0 } };
    ASSERT_TRUE( geo::findSelfIntersection( touching, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 2 );
    // Edge 1 runs back over edge 0 (adjacent, collinear overlap).
    const std::vector<Point2> fold = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 } };
    ASSERT_TRUE( geo::findSelfIntersection( fold, a, b ) );
    EXPECT_EQ( a, 0 );
    EXPECT_EQ( b, 1 );
    // Collinear but not folding back: a straight vertex is fine.
    const std::vector<Point2> straight = {
        { 0.0, 0.0 }, { 1.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 } };
    EXPECT_FALSE( geo::findSelfIntersection( straight, a, b ) );
}

TEST( Geometry, polyline_interpolation_and_extrapolation )
{
    const std::vector<Point2> line = {
        { 0.0, 1.0 }, { 10.0, 2.0 }, { 20.0, 0.0 } };
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 5.0 ), 1.5 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 10.0 ), 2.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 15.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 0.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, -4.0 ), 1.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( line, 25.0 ), 0.0 );
    EXPECT_DOUBLE_EQ( geo::polylineY( { { 3.0, 7.0 } }, 1.0 ), 7.0 );
    EXPECT_THROW( geo::polylineY( {}, 1.0 ), std::invalid_argument );
}

} // namespace
