#include <io/mpm_checkpoint_values.hpp>

#include <mpm_status_flags.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <map>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//! "name[k]: expected <expected>, found <value>".
std::string found( const CheckpointArray& a, const std::size_t k,
                   const std::string& expected, const double value )
{
    return a.name + "[" + std::to_string( k ) + "]: expected " + expected +
           ", found " +
           ( a.integer ? std::to_string( static_cast<long>( value ) )
                       : valueText( value ) );
}

//! The first value of `a` that fails `ok`, as found(expected), or "".
std::string firstFailing( const CheckpointArray& a,
                          const std::function<bool( double )>& ok,
                          const std::string& expected )
{
    const std::size_t size = a.integer ? a.integers.size() : a.reals.size();
    for ( std::size_t k = 0; k < size; ++k )
    {
        const double v = a.integer ? a.integers[k] : a.reals[k];
        if ( !ok( v ) )
            return found( a, k, expected, v );
    }
    return "";
}

//! The first coordinate of an active point outside the grid (the
//! expressions of GridGeometry::cellOf: such a point has no cell), or "".
std::string positionError( const CheckpointArray& a,
                           const std::vector<int>* status, const GridConfig& g )
{
    const double inv_h = 1.0 / g.cell_size_m;
    for ( std::size_t k = 0; k < a.reals.size(); ++k )
    {
        const std::size_t p = k / 2, axis = k % 2;
        if ( status && p < status->size() && ( *status )[p] != point_active )
            continue;
        const double origin = g.origin_m[axis];
        const double cell = ( a.reals[k] - origin ) * inv_h;
        if ( !( cell >= 0.0 && cell < g.cells[axis] ) )
            return found(
                a, k,
                "the position of an active point inside the grid, " +
                    std::string( axis == 0 ? "x" : "y" ) + " in [" +
                    valueText( origin ) + ", " +
                    valueText( origin + g.cells[axis] * g.cell_size_m ) +
                    ") m (point " + std::to_string( p ) + ")",
                a.reals[k] );
    }
    return "";
}

//! The loosest saturation bounds of material m over the case's materials
//! and every stage's (a stage lists the effective materials).
std::pair<double, double> saturationRange( const CaseConfig& config,
                                           const int m )
{
    double lo = 1.0, hi = 0.0;
    const auto take = [&]( const std::vector<MaterialConfig>& materials )
    {
        if ( m < 0 || m >= static_cast<int>( materials.size() ) )
            return;
        const RetentionConfig& r = materials[m].retention;
        const double low = r.model == RetentionType::Saturated
                               ? r.saturated_saturation
                               : r.residual_saturation;
        lo = std::min( lo, low );
        hi = std::max( hi, r.saturated_saturation );
    };
    take( config.materials );
    for ( const StageConfig& stage : config.stages )
        take( stage.materials );
    return { lo, hi };
}

//! True if the array is one of `names`.
bool is( const CheckpointArray& a, std::initializer_list<const char*> names )
{
    for ( const char* name : names )
        if ( a.name == name )
            return true;
    return false;
}

//! "particles/id_p[k]: expected a unique point id, ..." of the first repeat.
std::string repeatedId( const CheckpointArray& ids )
{
    std::map<int, std::size_t> first;
    for ( std::size_t k = 0; k < ids.integers.size(); ++k )
    {
        const auto [it, inserted] = first.emplace( ids.integers[k], k );
        if ( !inserted )
            return found( ids, k,
                          "a unique point id (it is also " + ids.name + "[" +
                              std::to_string( it->second ) + "])",
                          ids.integers[k] );
    }
    return "";
}

std::string saturationError( const CheckpointArray& s,
                             const CheckpointArray* material,
                             const CaseConfig& config )
{
    constexpr double tolerance = 1.0e-12;
    for ( std::size_t k = 0; k < s.reals.size(); ++k )
    {
        const int m = material && k < material->integers.size()
                          ? material->integers[k]
                          : 0;
        const auto [lo, hi] = saturationRange( config, m );
        if ( !( s.reals[k] >= lo - tolerance && s.reals[k] <= hi + tolerance ) )
            return found( s, k,
                          "a degree of saturation in [S_res, S_sat] = [" +
                              valueText( lo ) + ", " + valueText( hi ) +
                              "] of the point's material",
                          s.reals[k] );
    }
    return "";
}

} // namespace

//---------------------------------------------------------------------------//
std::string valueText( const double value )
{
    char buf[32];
    std::snprintf( buf, sizeof buf, "%.6g", value );
    return buf;
}

//---------------------------------------------------------------------------//
std::string stateValueError( const Checkpoint& c, const CaseConfig& config,
                             const StateBounds& bounds )
{
    // Every real value finite.
    for ( const CheckpointArray& a : c.arrays )
    {
        std::string error = firstFailing(
            a, []( const double v ) { return std::isfinite( v ); },
            "a finite number" );
        if ( !error.empty() )
            return error;
    }
    const CheckpointArray* status = c.find( "particles/status_p" );
    if ( status )
    {
        std::string error = firstFailing(
            *status,
            []( const double v )
            { return v == point_removed || v == point_active; },
            "a point status, 0 (removed) or 1 (active)" );
        if ( !error.empty() )
            return error;
        const auto removed =
            std::count( status->integers.begin(), status->integers.end(),
                        static_cast<int>( point_removed ) );
        if ( removed != c.num_removed )
            return "num_removed: expected the number of removed points in " +
                   status->name + ", " + std::to_string( removed ) +
                   ", found " + std::to_string( c.num_removed );
    }
    const std::vector<int>* active = status ? &status->integers : nullptr;

    const GridConfig& g = config.grid;
    const double nodes = ( g.cells[0] + 1.0 ) * ( g.cells[1] + 1.0 );
    const auto positive = []( const double v ) { return v > 0.0; };
    const auto non_negative = []( const double v ) { return v >= 0.0; };
    for ( const CheckpointArray& a : c.arrays )
    {
        std::string error;
        if ( a.name == "particles/id_p" )
            error = repeatedId( a );
        else if ( a.name == "particles/x_p" || a.name == "particles/x0_p" )
            error = positionError( a, active, g );
        else if ( a.name == "particles/m_p" )
            error = firstFailing( a, positive, "a mass > 0 kg" );
        else if ( a.name == "particles/vol_p" || a.name == "particles/vol0_p" )
            error = firstFailing(
                a,
                [&]( const double v )
                { return v > 0.0 && v <= bounds.max_volume_m3; },
                "a volume in (0, " + valueText( bounds.max_volume_m3 ) +
                    "] m^3 (at most the grid's area x 1 m)" );
        else if ( is( a,
                      { "particles/v_p", "water/v_w_p", "grid/v_i", "grid/dv_i",
                        "water_grid/v_w_i", "water_grid/dv_w_i" } ) )
            error = firstFailing(
                a,
                [&]( const double v )
                { return std::abs( v ) <= bounds.max_speed_m_per_s; },
                "a velocity of at most " +
                    valueText( bounds.max_speed_m_per_s ) +
                    " m/s (solver.instability_speed_factor x the fastest "
                    "wave, where a run stops as unstable)" );
        else if ( is( a, { "particles/sigma_p", "water/p_w_p",
                           "water/p_w_held_p" } ) )
            error = firstFailing(
                a,
                [&]( const double v )
                { return std::abs( v ) <= bounds.max_stress_pa; },
                "a stress of at most " + valueText( bounds.max_stress_pa ) +
                    " Pa (1000 x the stiffest modulus or the largest "
                    "load of the case)" );
        else if ( a.name == "particles/eps_p_bar_p" )
            error = firstFailing( a, non_negative, "a plastic strain >= 0" );
        else if ( a.name == "water/S_p" )
            error =
                saturationError( a, c.find( "particles/material_p" ), config );
        else if ( a.name == "water/n_p" )
            error = firstFailing(
                a, []( const double v ) { return v > 0.0 && v < 1.0; },
                "a porosity in (0, 1)" );
        else if ( a.name == "water/k_rel_p" )
            error = firstFailing(
                a, []( const double v ) { return v >= 0.0 && v <= 1.0; },
                "a relative permeability in [0, 1]" );
        else if ( a.name == "water/dS_dp_p" )
            error = firstFailing( a, non_negative, "dS/dp_w >= 0 1/Pa" );
        else if ( a.name == "water/inflow_weight_p" )
            error = firstFailing( a, non_negative, "an inflow weight >= 0" );
        else if ( a.name == "grid/flags_i" || a.name == "water_grid/flags_w_i" )
            error = firstFailing(
                a,
                []( const double v )
                { return v >= node_free && v <= node_fixed; },
                "node flags 0..3 (fix x = 1, fix y = 2)" );
        else if ( a.name == "grid/active_i" )
            error = firstFailing(
                a, [&]( const double v ) { return v >= 0.0 && v < nodes; },
                "a node index in 0.." + valueText( nodes - 1.0 ) );
        if ( !error.empty() )
            return error;
    }
    if ( c.grid_num_active < 0 || c.grid_num_active > nodes )
        return "grid_num_active: expected 0.." + valueText( nodes ) +
               " nodes, found " + std::to_string( c.grid_num_active );
    return "";
}

} // namespace Impl
} // namespace mpm
