#include <io/mpm_checkpoint_check.hpp>

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

bool startsWith( const std::string& text, const std::string& prefix )
{
    return text.rfind( prefix, 0 ) == 0;
}

} // namespace

//---------------------------------------------------------------------------//
std::string checkpointRangeError( const Checkpoint& c,
                                  const CaseConfig& config )
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
                return "load_groups[" + std::to_string( g ) +
                       "]: expected load indices in 0.." +
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
        if ( !startsWith( a.name, "particles/" ) &&
             !startsWith( a.name, "water/" ) )
            continue;
        const auto it = std::find_if( a.reals.begin(), a.reals.end(),
                                      []( const double v )
                                      { return !std::isfinite( v ); } );
        if ( it != a.reals.end() )
            return a.name + "[" + std::to_string( it - a.reals.begin() ) +
                   "]: expected a finite number, found " +
                   std::to_string( *it );
    }
    return "";
}

} // namespace mpm
