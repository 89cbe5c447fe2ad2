#include <io/mpm_checkpoint_check.hpp>
#include <io/mpm_checkpoint_values.hpp>

#include <algorithm>
#include <cmath>

namespace mpm
{
namespace
{
//! "name[k] = value" of the first integer outside [lo, hi), or "".
std::string intOutside( const CheckpointArray& a, const long lo, const long hi )
{
    for ( std::size_t k = 0; k < a.integers.size(); ++k )
        if ( a.integers[k] < lo || a.integers[k] >= hi )
            return a.name + "[" + std::to_string( k ) +
                   "]: expected an index in " + std::to_string( lo ) + ".." +
                   std::to_string( hi - 1 ) + ", found " +
                   std::to_string( a.integers[k] );
    return "";
}

//! Why the point conditions of the checkpoint's stage do not fit its points
//! (num_inflows: the stage's inflows), or "".
std::string conditionsError( const Checkpoint& c, const long num_inflows )
{
    // Each load's count of points: the points whose group holds it.
    const CheckpointArray* load_p = c.find( "particles/load_p" );
    for ( std::size_t l = 0; l < c.load_counts.size(); ++l )
    {
        long count = 0;
        if ( load_p )
            for ( const int g : load_p->integers )
                if ( g >= 0 && g < static_cast<long>( c.load_groups.size() ) &&
                     std::count( c.load_groups[g].begin(),
                                 c.load_groups[g].end(), int( l ) ) > 0 )
                    ++count;
        if ( c.load_counts[l] != count )
            return "conditions/load_counts[" + std::to_string( l ) +
                   "]: expected the number of points carrying load " +
                   std::to_string( l ) + " in particles/load_p, " +
                   std::to_string( count ) + ", found " +
                   std::to_string( c.load_counts[l] );
    }
    const CheckpointArray* inflow_p = c.find( "water/inflow_p" );
    const auto fed = [&]( const long f )
    {
        return inflow_p && std::count( inflow_p->integers.begin(),
                                       inflow_p->integers.end(), int( f ) ) > 0;
    };
    for ( std::size_t f = 0; f < c.inflow_volumes.size(); ++f )
    {
        const double v = c.inflow_volumes[f];
        const bool points = static_cast<long>( f ) < num_inflows && fed( f );
        if ( !std::isfinite( v ) || v < 0.0 || ( points && !( v > 0.0 ) ) )
            return "conditions/inflow_volumes[" + std::to_string( f ) +
                   "]: expected the volume of the inflow's points, finite " +
                   ( points ? "and > 0" : "and >= 0" ) + " m^3, found " +
                   Impl::valueText( v );
    }
    for ( std::size_t f = 0; f < c.inflow_lengths_m.size(); ++f )
        if ( !std::isfinite( c.inflow_lengths_m[f] ) ||
             c.inflow_lengths_m[f] < 0.0 )
            return "conditions/inflow_lengths_m[" + std::to_string( f ) +
                   "]: expected a finite length >= 0 m, found " +
                   Impl::valueText( c.inflow_lengths_m[f] );
    if ( !( c.next_surface_update_s >= 0.0 ) )
        return "conditions/next_surface_update_s: expected a time >= 0 s, "
               "found " +
               Impl::valueText( c.next_surface_update_s );
    return "";
}

} // namespace

//---------------------------------------------------------------------------//
std::string checkpointRangeError( const Checkpoint& c, const CaseConfig& config,
                                  const Impl::StateBounds& bounds )
{
    auto bad = []( const double v ) { return !std::isfinite( v ) || v < 0.0; };
    const long n = c.identity.num_points;
    if ( bad( c.time_s ) )
        return "time_s: expected a finite time >= 0 s, found " +
               std::to_string( c.time_s );
    if ( c.step < 0 )
        return "step: expected >= 0, found " + std::to_string( c.step );
    if ( bad( c.wall_s ) )
        return "wall_s: expected a finite time >= 0 s, found " +
               std::to_string( c.wall_s );
    if ( c.snapshots.count < 0 )
        return "snapshot_count: expected >= 0, found " +
               std::to_string( c.snapshots.count );
    if ( c.num_removed < 0 || c.num_removed > n )
        return "num_removed: expected 0.." + std::to_string( n ) + ", found " +
               std::to_string( c.num_removed );
    if ( c.loop.stage > config.stages.size() )
        return "loop.stage: expected a stage index in 0.." +
               std::to_string( config.stages.size() ) + ", found " +
               std::to_string( c.loop.stage );
    // The current stage's point conditions index its lists (-1: none; no
    // list once every stage has ended).
    const StageConfig* stage = c.loop.stage < config.stages.size()
                                   ? &config.stages[c.loop.stage]
                                   : nullptr;
    const auto length = []( const auto& list )
    { return static_cast<long>( list.size() ); };
    const long num_loads = stage ? length( stage->loads ) : 0;
    const long num_groups = stage ? length( c.load_groups ) : 0;
    const long num_conditions = stage ? length( stage->pore_pressures ) : 0;
    const long num_inflows = stage ? length( stage->inflows ) : 0;
    for ( std::size_t g = 0; g < c.load_groups.size(); ++g )
        for ( const int l : c.load_groups[g] )
            if ( l < 0 || l >= num_loads )
                return "conditions/load_group_members (group " +
                       std::to_string( g ) + "): expected load indices in 0.." +
                       std::to_string( num_loads - 1 ) + ", found " +
                       std::to_string( l );
    for ( const CheckpointArray& a : c.arrays )
    {
        std::string error;
        if ( a.name == "particles/material_p" )
            error = intOutside( a, 0,
                                static_cast<long>( config.materials.size() ) );
        else if ( a.name == "particles/id_p" )
            error = intOutside( a, 0, n );
        else if ( a.name == "particles/load_p" )
            error = intOutside( a, -1, num_groups );
        else if ( a.name == "water/p_w_condition_p" )
            error = intOutside( a, -1, num_conditions );
        else if ( a.name == "water/inflow_p" )
            error = intOutside( a, -1, num_inflows );
        if ( !error.empty() )
            return error;
    }
    if ( std::string error = Impl::stateValueError( c, config, bounds );
         !error.empty() )
        return error;
    return conditionsError( c, num_inflows );
}

} // namespace mpm
