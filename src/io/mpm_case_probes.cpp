#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_probes.hpp>
#include <io/mpm_case_shapes.hpp>
#include <io/mpm_toml_access.hpp>

#include <set>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
ProbesConfig readProbes( const toml::table& table, const GridConfig* grid,
                         Diagnostics& diag )
{
    ProbesConfig probes;
    TableReader r( table, "probes", diag );
    checkTableKeys( r, "[probes]" );
    probes.interval_s =
        r.number( "interval_s", Range::above( 0.0 ), "s", Need::Required )
            .value_or( 0.0 );
    const auto* points =
        r.tableArray( "points", Need::Required, "[[probes.points]]" );
    if ( !points )
        return probes;
    std::set<std::string> names;
    forEachTable(
        *points, "probes.points", diag, { "name", "position_m" },
        "[[probes.points]]",
        [&]( TableReader& p )
        {
            ProbeConfig probe;
            if ( const auto name = p.string( "name", Need::Required ) )
            {
                probe.name = *name;
                if ( !names.insert( *name ).second )
                    diag.keyError(
                        *p.find( "name" ), p.keyPath( "name" ),
                        "the probe name '" + *name +
                            "' is used twice; names must be unique" );
            }
            if ( const auto x = p.point( "position_m", "m", Need::Required ) )
            {
                probe.position_m = *x;
                const std::string outside =
                    grid ? outsideGridText( *grid, *x ) : "";
                if ( !outside.empty() )
                    diag.keyError( *p.find( "position_m" ),
                                   p.keyPath( "position_m" ),
                                   "expected a point " + outside );
            }
            probes.points.push_back( probe );
        } );
    return probes;
}

} // namespace Impl
} // namespace mpm
