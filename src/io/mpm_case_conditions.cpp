#include <io/mpm_case_conditions.hpp>
#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_shapes.hpp>
#include <io/mpm_toml_access.hpp>

#include <optional>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//---------------------------------------------------------------------------//
// box_m = [[x_min, y_min], [x_max, y_max]], or nothing after an error.
std::optional<std::array<Point2, 2>> readBox( TableReader& r )
{
    const std::string expected = "a box [[x_min, y_min], [x_max, y_max]] in m";
    const toml::node* node = r.node( "box_m", Need::Required,
                                     expected + " (required for where = "
                                                "\"box\")" );
    if ( !node )
        return std::nullopt;
    const std::string path = r.keyPath( "box_m" );
    const toml::array* arr = node->as_array();
    if ( !arr || arr->size() != 2 || !arr->get( 0 )->is_array() ||
         !arr->get( 1 )->is_array() )
    {
        r.diag().mismatch( *node, path, expected );
        return std::nullopt;
    }
    const auto lo =
        readPoint( *arr->get( 0 ), indexed( path, 0 ), "m", r.diag() );
    const auto hi =
        readPoint( *arr->get( 1 ), indexed( path, 1 ), "m", r.diag() );
    if ( !lo || !hi )
        return std::nullopt;
    if ( !( ( *hi )[0] >= ( *lo )[0] && ( *hi )[1] >= ( *lo )[1] ) )
    {
        r.diag().keyError(
            *arr->get( 1 ), indexed( path, 1 ),
            "expected the upper-right corner [x_max, y_max] with x_max >= " +
                formatNumber( ( *lo )[0] ) + " m and y_max >= " +
                formatNumber( ( *lo )[1] ) + " m (the lower-left corner " +
                indexed( path, 0 ) + "), found [" + formatNumber( ( *hi )[0] ) +
                ", " + formatNumber( ( *hi )[1] ) + "] m" );
        return std::nullopt;
    }
    return std::array<Point2, 2>{ *lo, *hi };
}

} // namespace

//---------------------------------------------------------------------------//
PointSelection readSelection( TableReader& r, const bool polyline_allowed )
{
    PointSelection selection;
    // In the order of PointSelection::Kind.
    std::vector<std::string> kinds = { "box",    "surface_cells", "top",
                                       "bottom", "left",          "right",
                                       "all",    "surface_points" };
    if ( polyline_allowed )
        kinds.push_back( "polyline" );
    const toml::node* where_node = r.find( "where" );
    if ( !polyline_allowed && where_node &&
         where_node->value_or<std::string>( "" ) == "polyline" )
    {
        r.diag().keyError( *where_node, r.keyPath( "where" ),
                           "\"polyline\" is only for [[stages.inflows]]; "
                           "expected one of " +
                               quotedList( kinds, '"' ) );
        return selection;
    }
    const auto where = r.choice( "where", kinds, Need::Required );
    if ( where )
        selection.kind = static_cast<PointSelection::Kind>( *where );
    if ( where && selection.kind == PointSelection::Kind::Box )
    {
        if ( const auto box = readBox( r ) )
            selection.box_m = *box;
    }
    else if ( where && r.find( "box_m" ) )
        r.diag().keyError( *r.find( "box_m" ), r.keyPath( "box_m" ),
                           "only for where = \"box\"; remove it or change "
                           "'where'" );
    if ( polyline_allowed && where &&
         selection.kind != PointSelection::Kind::Polyline )
        for ( const char* key : { "polyline_m", "measured_on" } )
            if ( const toml::node* node = r.find( key ) )
                r.diag().keyError( *node, r.keyPath( key ),
                                   "only for where = \"polyline\"; remove "
                                   "it or change 'where'" );
    return selection;
}

//---------------------------------------------------------------------------//
TimeFunction readTimeFunction( TableReader& r )
{
    return readTimeFunction( r, "time_function", Range::any(), "" );
}

//---------------------------------------------------------------------------//
TimeFunction readTimeFunction( TableReader& r, const char* key,
                               const Range& values, const char* unit )
{
    const std::string value =
        *unit ? std::string( "value in " ) + unit : std::string( "factor" );
    const std::string expected =
        "an array of at least one pair [[t_s, " + value +
        "], ...] (stage time in s, strictly increasing, and a " + value + ")";
    const toml::node* node = r.find( key );
    if ( !node )
        return {};
    const std::string path = r.keyPath( key );
    const toml::array* arr = node->as_array();
    if ( !arr || arr->empty() )
    {
        r.diag().mismatch( *node, path, expected );
        return {};
    }
    TimeFunction function;
    for ( std::size_t k = 0; k < arr->size(); ++k )
    {
        const toml::node& pair_node = *arr->get( k );
        const toml::array* pair = pair_node.as_array();
        if ( !pair || pair->size() != 2 )
        {
            r.diag().mismatch( pair_node, indexed( path, k ),
                               "a pair [t_s, " + value + "]" );
            return {};
        }
        const auto t = readNumber( *pair->get( 0 ), indexed( path, k ) + "[0]",
                                   Range::atLeast( 0.0 ), "s", r.diag() );
        const auto f = readNumber( *pair->get( 1 ), indexed( path, k ) + "[1]",
                                   values, unit, r.diag() );
        if ( !t || !f )
            return {};
        if ( !function.empty() && !( *t > function.back()[0] ) )
        {
            r.diag().keyError(
                *pair->get( 0 ), indexed( path, k ) + "[0]",
                "expected a time > " + formatNumber( function.back()[0] ) +
                    " s (the times of a time function must increase "
                    "strictly), found " +
                    formatNumber( *t ) );
            return {};
        }
        function.push_back( { *t, *f } );
    }
    return function;
}

//---------------------------------------------------------------------------//
std::vector<double> readSnapshotTimes( TableReader& r )
{
    const toml::node* node = r.find( "snapshot_times_s" );
    if ( !node )
        return {};
    const std::string path = r.keyPath( "snapshot_times_s" );
    const toml::array* arr = node->as_array();
    if ( !arr )
    {
        r.diag().mismatch(
            *node, path, "an array of stage times in s, strictly increasing" );
        return {};
    }
    std::vector<double> times;
    for ( std::size_t k = 0; k < arr->size(); ++k )
    {
        const auto t = readNumber( *arr->get( k ), indexed( path, k ),
                                   Range::above( 0.0 ), "s", r.diag() );
        if ( !t )
            return {};
        if ( !times.empty() && !( *t > times.back() ) )
        {
            r.diag().keyError( *arr->get( k ), indexed( path, k ),
                               "expected a time > " +
                                   formatNumber( times.back() ) +
                                   " s (snapshot times must increase "
                                   "strictly), found " +
                                   formatNumber( *t ) );
            return {};
        }
        times.push_back( *t );
    }
    return times;
}

//---------------------------------------------------------------------------//
std::vector<BoundaryConfig> readBoundaries( const toml::array& array,
                                            const std::string& prefix,
                                            const Analysis& analysis,
                                            const GridConfig* grid,
                                            Diagnostics& diag )
{
    std::vector<BoundaryConfig> result;
    forEachTable(
        array, prefix, diag, keysOf( "[[boundaries]]" ),
        prefix == "boundaries" ? "[[boundaries]]" : "[[stages.boundaries]]",
        [&]( TableReader& r )
        {
            const std::string& path = r.path();
            BoundaryConfig bc;
            const auto where = r.choice( "where",
                                         { "left", "right", "bottom", "top",
                                           "below_polyline", "polyline" },
                                         Need::Required );
            const auto condition =
                r.choice( "condition", { "fixed", "fix_x", "fix_y", "none" },
                          Need::Required );
            if ( where )
                bc.where = static_cast<BoundarySelector>( *where );
            if ( condition == 3 )
                bc.constrains_solid = false; // condition stays Fixed, unused
            else if ( condition )
                bc.condition = static_cast<BoundaryCondition>( *condition );
            if ( !rejectIfDry( r, "hydraulic", analysis ) )
                if ( const auto h =
                         r.choice( "hydraulic", { "impermeable", "drained" },
                                   Need::Optional ) )
                    bc.hydraulic = static_cast<HydraulicCondition>( *h );
            if ( !bc.constrains_solid && isDry( analysis ) )
                diag.keyError( *r.find( "condition" ), r.keyPath( "condition" ),
                               "\"none\" (a purely hydraulic boundary) is " +
                                   twoPhaseOnlyText() );
            else if ( !bc.constrains_solid && !r.find( "hydraulic" ) )
                r.missing(
                    "hydraulic",
                    "one of \"impermeable\", \"drained\" (required for "
                    "condition = \"none\", a purely hydraulic boundary)" );
            if ( where && bc.where == BoundarySelector::BelowPolyline )
            {
                if ( auto line =
                         r.points( "polyline_m", 2, "m", Need::Required ) )
                {
                    checkPolyline( *line, *r.find( "polyline_m" ),
                                   path + ".polyline_m", diag );
                    if ( grid )
                        warnPolylineOutsideGrid(
                            *line, *r.find( "polyline_m" ),
                            path + ".polyline_m", *grid,
                            "it selects only the grid's nodes below it, the "
                            "line extended horizontally beyond its ends",
                            diag );
                    bc.polyline_m = *line;
                }
            }
            else if ( where && bc.where == BoundarySelector::Polyline )
            {
                if ( auto line =
                         r.points( "polyline_m", 2, "m", Need::Required ) )
                {
                    checkWallPolyline( *line, *r.find( "polyline_m" ),
                                       path + ".polyline_m", grid, diag );
                    bc.polyline_m = *line;
                }
            }
            else if ( where && r.find( "polyline_m" ) )
                diag.keyError( *r.find( "polyline_m" ), path + ".polyline_m",
                               "only for where = \"below_polyline\" or "
                               "\"polyline\"; remove it or change 'where'" );
            result.push_back( bc );
        } );
    return result;
}

//---------------------------------------------------------------------------//
std::vector<PorePressureCondition> readPorePressures( const toml::array& array,
                                                      const std::string& prefix,
                                                      Diagnostics& diag )
{
    return readTablesOf<PorePressureCondition>(
        "[[stages.pore_pressures]]", array, prefix, diag,
        [&]( TableReader& r, PorePressureCondition& condition )
        {
            condition.points = readSelection( r, false );
            const toml::node* hold = r.find( "hold" );
            condition.hold_initial =
                hold && r.choice( "hold", { "initial" }, Need::Optional );
            if ( hold && r.find( "pressure_pa" ) )
                diag.keyError(
                    *r.find( "pressure_pa" ), r.keyPath( "pressure_pa" ),
                    "not allowed with hold: a held pore pressure "
                    "keeps each point's p_w at the stage start; give "
                    "either pressure_pa or hold" );
            else if ( !hold )
                condition.pressure_pa =
                    r.number( "pressure_pa", Range::any(),
                              "Pa (or hold = \"initial\")", Need::Required )
                        .value_or( 0.0 );
            if ( hold && r.find( "time_function" ) )
                diag.keyError(
                    *r.find( "time_function" ), r.keyPath( "time_function" ),
                    "not allowed with hold: the held p_w of each point "
                    "is its value at the stage start" );
            else
                condition.time_function = readTimeFunction( r );
        } );
}

//---------------------------------------------------------------------------//
std::vector<PointLoad> readLoads( const toml::array& array,
                                  const std::string& prefix, Diagnostics& diag )
{
    return readTablesOf<PointLoad>(
        "[[stages.loads]]", array, prefix, diag,
        [&]( TableReader& r, PointLoad& load )
        {
            load.points = readSelection( r, false );
            load.traction_pa = r.point( "traction_pa", "Pa", Need::Required )
                                   .value_or( load.traction_pa );
            load.length_m =
                r.number( "length_m", Range::above( 0.0 ),
                          "m (the loaded boundary length)", Need::Required )
                    .value_or( load.length_m );
            load.time_function = readTimeFunction( r );
        } );
}

//---------------------------------------------------------------------------//
StaticStop readStaticStop( const toml::table& table, const std::string& path,
                           const bool quasi_static, Diagnostics& diag )
{
    TableReader r( table, path, diag );
    checkTableKeys( r, "[stages.static_stop]" );
    StaticStop stop;
    if ( quasi_static )
    {
        diag.keyError( table, path,
                       "only for type \"dynamic\"; a quasi_static "
                       "stage stops on ke_ratio_tolerance" );
        return stop;
    }
    stop.static_speed_m_per_s =
        r.number( "static_speed_m_per_s", Range::above( 0.0 ), "m/s",
                  Need::Required )
            .value_or( 0.0 );
    stop.slide_displacement_m =
        r.number( "slide_displacement_m", Range::above( 0.0 ), "m",
                  Need::Optional )
            .value_or( stop.slide_displacement_m );
    stop.window_s =
        r.number( "window_s", Range::above( 0.0 ), "s", Need::Optional )
            .value_or( stop.window_s );
    stop.speed_percentile =
        r.number( "speed_percentile",
                  Range::interval( 0.0, true, 100.0, false ), "%",
                  Need::Optional )
            .value_or( stop.speed_percentile );
    return stop;
}

//---------------------------------------------------------------------------//
// initial_stress_k0: K0 in (0, 3]; the geostatic field needs gravity along
// -y (sigma_v from the weight of the column above each point).
void readInitialStress( TableReader& r, const std::string& path,
                        StageConfig& stage, Diagnostics& diag )
{
    const auto k0 =
        r.number( "initial_stress_k0", Range::interval( 0.0, false, 3.0, true ),
                  "(sigma_h / sigma_v)", Need::Optional );
    if ( !k0 )
        return;
    stage.initial_stress_k0 = *k0;
    const Point2& g = stage.gravity_m_per_s2;
    if ( g[0] != 0.0 || !( g[1] < 0.0 ) )
        diag.keyError( *r.find( "initial_stress_k0" ),
                       path + ".initial_stress_k0",
                       "needs the stage's gravity_m_per_s2 along -y ([0, -g], "
                       "g > 0: the vertical stress is the weight of the "
                       "column above a point), found [" +
                           formatNumber( g[0] ) + ", " + formatNumber( g[1] ) +
                           "] m/s^2" );
}

//---------------------------------------------------------------------------//
void readStageTiming( TableReader& r, const std::string& path,
                      const bool type_known, StageConfig& stage,
                      Diagnostics& diag )
{
    const bool quasi_static = stage.type == StageType::QuasiStatic;
    stage.gravity_m_per_s2 =
        r.point( "gravity_m_per_s2", "m/s^2", Need::Optional )
            .value_or( stage.gravity_m_per_s2 );
    stage.damping =
        r.number( "damping", Range::interval( 0.0, false, 1.0, true ), "",
                  Need::Optional )
            .value_or( quasi_static ? 0.7 : 0.0 );
    stage.duration_s =
        r.number( "duration_s", Range::above( 0.0 ), "s", Need::Required )
            .value_or( 0.0 );
    if ( type_known && !quasi_static && r.find( "ke_ratio_tolerance" ) )
        diag.keyError( *r.find( "ke_ratio_tolerance" ),
                       path + ".ke_ratio_tolerance",
                       "only for type \"quasi_static\"; a dynamic "
                       "stage runs for duration_s" );
    else
        stage.ke_ratio_tolerance =
            r.number( "ke_ratio_tolerance",
                      Range::interval( 0.0, true, 1.0, true ), "",
                      Need::Optional )
                .value_or( stage.ke_ratio_tolerance );
    if ( const auto* t = r.subTable( "static_stop", Need::Optional ) )
        stage.static_stop = readStaticStop( *t, path + ".static_stop",
                                            type_known && quasi_static, diag );
    stage.snapshot_interval_s =
        r.number( "snapshot_interval_s", Range::atLeast( 0.0 ),
                  "s (0 = at the stage end only)", Need::Optional )
            .value_or( 0.0 );
    stage.snapshot_times_s = readSnapshotTimes( r );
    stage.reset_displacement =
        r.boolean( "reset_displacement", Need::Optional ).value_or( false );
    readInitialStress( r, path, stage, diag );
}

} // namespace Impl
} // namespace mpm
