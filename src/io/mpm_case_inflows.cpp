#include <case/mpm_polyline_cells.hpp>
#include <io/mpm_case_conditions.hpp>
#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_shapes.hpp>
#include <io/mpm_toml_access.hpp>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//---------------------------------------------------------------------------//
/*!
  polyline_m and measured_on of an inflow on a polyline: at least two
  points, consecutive ones distinct; measured on the horizontal, x must not
  turn back and the line must span some width. Sets the selection's line
  and the inflow's length (polylineLength); warns of points outside the
  grid.
*/
void readInflowPolyline( TableReader& r, WaterInflow& inflow,
                         const GridConfig* grid )
{
    PointSelection& selection = inflow.points;
    if ( const auto measure = r.choice(
             "measured_on", { "along_line", "horizontal" }, Need::Optional ) )
        selection.polyline_measure = static_cast<LineMeasure>( *measure );
    const bool horizontal =
        selection.polyline_measure == LineMeasure::Horizontal;
    const auto line = r.points( "polyline_m", 2, "m", Need::Required );
    if ( !line )
        return;
    const toml::node& node = *r.find( "polyline_m" );
    const std::string path = r.keyPath( "polyline_m" );
    const toml::array& points = *node.as_array();
    double direction = 0.0; // sign of the first step along x
    for ( std::size_t k = 1; k < line->size(); ++k )
    {
        const Point2& a = ( *line )[k - 1];
        const Point2& b = ( *line )[k];
        if ( a == b )
        {
            r.diag().keyError( *points.get( k ), indexed( path, k ),
                               "expected a point other than the previous "
                               "one (a segment of zero length), found [" +
                                   formatNumber( b[0] ) + ", " +
                                   formatNumber( b[1] ) + "] m twice" );
            return;
        }
        const double dx = b[0] - a[0];
        if ( horizontal && direction * dx < 0.0 )
        {
            r.diag().keyError(
                *points.get( k ), indexed( path, k ),
                "expected x " + std::string( direction > 0.0 ? ">=" : "<=" ) +
                    " " + formatNumber( a[0] ) +
                    " m (with measured_on = \"horizontal\" the line must not "
                    "turn back along x: its projection would count that "
                    "rain twice), found x = " +
                    formatNumber( b[0] ) + " m" );
            return;
        }
        if ( direction == 0.0 && dx != 0.0 )
            direction = dx > 0.0 ? 1.0 : -1.0;
    }
    if ( horizontal && direction == 0.0 )
    {
        r.diag().keyError( node, path,
                           "expected a line with a horizontal extent "
                           "(measured_on = \"horizontal\" measures the rain "
                           "on its projection), found a vertical line at x "
                           "= " +
                               formatNumber( line->front()[0] ) + " m" );
        return;
    }
    if ( grid )
        warnPolylineOutsideGrid( *line, node, path, *grid,
                                 "its pieces outside the grid feed no cell: "
                                 "their flux goes to the cells the line "
                                 "crosses inside it",
                                 r.diag() );
    selection.polyline_m = *line;
    inflow.length_m = polylineLength( *line, selection.polyline_measure );
}

//! 1 mm/h in m/s.
constexpr double mm_per_h = 1.0e-3 / 3600.0;

/*!
  \brief The time function of a hyetograph's pairs [t_s, i]: each
  intensity holds from its time to the next pair's (the last to the
  stage's end), zero before the first; a jump at each pair's time (two
  pairs at that time: the intensity before, then the one after).
*/
TimeFunction hyetographSteps( const TimeFunction& pairs )
{
    TimeFunction steps;
    if ( pairs.empty() )
        return steps;
    if ( pairs.front()[0] > 0.0 )
        steps = { { 0.0, 0.0 }, { pairs.front()[0], 0.0 } };
    for ( std::size_t k = 0; k < pairs.size(); ++k )
    {
        if ( k > 0 )
            steps.push_back( { pairs[k][0], pairs[k - 1][1] } );
        steps.push_back( pairs[k] );
    }
    return steps;
}

/*!
  \brief The rain's intensity and its course in time: flux_m_per_s and an
  optional time_function with factors >= 0, or hyetograph_mm_per_h (the
  intensity in mm/h of consecutive blocks of time) instead of both.
*/
void readRainIntensity( TableReader& r, WaterInflow& inflow )
{
    Diagnostics& diag = r.diag();
    if ( r.find( "hyetograph_mm_per_h" ) )
    {
        for ( const char* key : { "flux_m_per_s", "time_function" } )
            if ( const toml::node* node = r.find( key ) )
                diag.keyError( *node, r.keyPath( key ),
                               "not allowed with hyetograph_mm_per_h: the "
                               "hyetograph gives the intensity and its "
                               "course in time" );
        inflow.flux_m_per_s = mm_per_h;
        inflow.time_function = hyetographSteps( readTimeFunction(
            r, "hyetograph_mm_per_h", Range::atLeast( 0.0 ), "mm/h" ) );
        return;
    }
    inflow.flux_m_per_s =
        r.number( "flux_m_per_s", Range::atLeast( 0.0 ),
                  "m/s (rainfall intensity, volume per area and time)",
                  Need::Required )
            .value_or( 0.0 );
    inflow.time_function = readTimeFunction( r );
    for ( std::size_t k = 0; k < inflow.time_function.size(); ++k )
        if ( inflow.time_function[k][1] < 0.0 )
        {
            diag.keyError( *r.find( "time_function" ),
                           r.keyPath( "time_function" ),
                           "expected factors >= 0 on a rain (a negative one "
                           "would take water out: evaporation is not "
                           "modelled), found " +
                               formatNumber( inflow.time_function[k][1] ) +
                               " in pair " + std::to_string( k ) );
            return;
        }
}

} // namespace

//---------------------------------------------------------------------------//
std::vector<WaterInflow> readInflows( const toml::array& array,
                                      const std::string& prefix,
                                      const GridConfig* grid,
                                      Diagnostics& diag )
{
    return readTablesOf<WaterInflow>(
        "[[stages.inflows]]", array, prefix, diag,
        [&]( TableReader& r, WaterInflow& inflow )
        {
            inflow.points = readSelection( r, true );
            readRainIntensity( r, inflow );
            const toml::node* follow = r.find( "follow_surface_s" );
            const toml::node* length = r.find( "length_m" );
            const bool on_polyline =
                r.find( "where" ) &&
                inflow.points.kind == PointSelection::Kind::Polyline;
            if ( follow )
            {
                inflow.follow_surface_interval_s =
                    r.number( "follow_surface_s", Range::above( 0.0 ),
                              "s (how often the surface is re-detected)",
                              Need::Required )
                        .value_or( 0.0 );
                if ( inflow.points.kind != PointSelection::Kind::SurfaceCells )
                    diag.keyError( *follow, r.keyPath( "follow_surface_s" ),
                                   "a rainfall that follows the surface needs "
                                   "where = \"surface_cells\"" );
                if ( length )
                    diag.keyError( *length, r.keyPath( "length_m" ),
                                   "not allowed with follow_surface_s: the "
                                   "length is the surface's current horizontal "
                                   "projection" );
            }
            else if ( on_polyline )
            {
                if ( length )
                    diag.keyError( *length, r.keyPath( "length_m" ),
                                   "not allowed with where = \"polyline\": the "
                                   "length is polyline_m's (along the line, or "
                                   "its horizontal projection with measured_on "
                                   "= \"horizontal\")" );
                readInflowPolyline( r, inflow, grid );
            }
            else if ( inflow.onGridEdge() )
            {
                if ( length )
                    diag.keyError( *length, r.keyPath( "length_m" ),
                                   "not allowed on a grid edge: the flux acts "
                                   "on the edge's nodes that touch soil" );
            }
            else
                inflow.length_m =
                    r.number( "length_m", Range::above( 0.0 ),
                              "m (the length of surface receiving the flux)",
                              Need::Required )
                        .value_or( inflow.length_m );
            inflow.ponding = r.boolean( "ponding", Need::Optional )
                                 .value_or( inflow.ponding );
        } );
}

} // namespace Impl
} // namespace mpm
