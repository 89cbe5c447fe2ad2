#include <solver/output/mpm_metrics.hpp>

#include <mpm_device_type.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mpm
{
nlohmann::json deformationMetrics( const HostSnapshot& snapshot,
                                   const double moved_threshold_m )
{
    double max_displacement = 0.0;
    double moved_area = 0.0;
    double max_x = -1.0e300;
    int max_point = -1;
    for ( int p = 0; p < snapshot.num_points; ++p )
    {
        if ( snapshot.status[p] != point_active )
            continue;
        const double ux = snapshot.displacement[2 * p];
        const double uy = snapshot.displacement[2 * p + 1];
        const double u = std::sqrt( ux * ux + uy * uy );
        if ( u > max_displacement )
        {
            max_displacement = u;
            max_point = snapshot.id[p];
        }
        if ( u > moved_threshold_m )
            moved_area += snapshot.vol[p];
        max_x = std::max( max_x, snapshot.x[2 * p] );
    }
    return { { "max_displacement_m", max_displacement },
             { "max_displacement_point", max_point },
             { "moved_area_m2", moved_area },
             { "moved_threshold_m", moved_threshold_m },
             { "max_x_m", max_x } };
}

nlohmann::json waterBalanceMetrics( const physics::WaterBalance& water )
{
    return {
        { "unit", "m3 of water (at its reference density) per m out "
                  "of plane" },
        { "stored_start", water.stored_start },
        { "stored_end", water.stored_end },
        { "carried_off_grid", water.carried_off_end - water.carried_off_start },
        { "stored_change", water.storedChange() },
        { "point_inflow", water.point_inflow },
        { "runoff", water.runoff },
        { "prescribed_pressure", water.prescribed },
        { "flow_in", water.flow_in },
        { "closure_error", water.closureError() },
        { "closure_error_relative", water.relativeClosureError() } };
}

nlohmann::json stageMetrics( const StageSummary& stage, const bool two_phase )
{
    nlohmann::json j = { { "name", stage.name },
                         { "type", stage.type },
                         { "steps", stage.steps },
                         { "duration_s", stage.duration_s },
                         { "dt_min_s", stage.dt_min_s },
                         { "dt_max_s", stage.dt_max_s },
                         { "stop_reason", stage.stop_reason },
                         { "max_speed_m_per_s", stage.max_speed_m_per_s } };
    if ( stage.type == "quasi_static" )
    {
        j["ke_ratio"] = stage.ke_ratio;
        j["converged"] = stage.converged;
    }
    if ( two_phase )
        j["water_balance"] = waterBalanceMetrics( stage.water );
    if ( stage.speed_percentile > 0.0 )
        j["static_stop"] = {
            { "speed_percentile", stage.speed_percentile },
            { "static_speed_m_per_s", stage.static_speed_m_per_s },
            { "speed_at_percentile_m_per_s",
              stage.speed_at_percentile_m_per_s },
            { "points_not_below_static_speed",
              stage.points_not_below_static_speed },
            { "allowed_points_not_below", stage.allowed_points_not_below } };
    return j;
}

//---------------------------------------------------------------------------//
void PorePressureExtremes::add( const HostSnapshot& snapshot,
                                const double time_s )
{
    if ( snapshot.p_w.empty() )
        return;
    std::vector<double> p_w;
    p_w.reserve( snapshot.p_w.size() );
    for ( std::size_t p = 0; p < snapshot.p_w.size(); ++p )
        if ( snapshot.status[p] == point_active )
            p_w.push_back( snapshot.p_w[p] );
    if ( p_w.empty() )
        return;
    // The 99th percentile as the value of rank floor(0.99 (n - 1)).
    const std::size_t rank =
        static_cast<std::size_t>( 0.99 * ( p_w.size() - 1 ) );
    std::nth_element( p_w.begin(), p_w.begin() + rank, p_w.end() );
    const double p99 = p_w[rank];
    const double largest = *std::max_element( p_w.begin() + rank, p_w.end() );
    if ( largest > max_pa )
    {
        max_pa = largest;
        max_time_s = time_s;
    }
    if ( p99 > p99_pa )
    {
        p99_pa = p99;
        p99_time_s = time_s;
    }
    seen = true;
}

void PorePressureExtremes::write( nlohmann::json& metrics ) const
{
    if ( !seen )
        return;
    metrics["pore_pressure_max_pa"] = max_pa;
    metrics["pore_pressure_max_time_s"] = max_time_s;
    metrics["pore_pressure_p99_pa"] = p99_pa;
    metrics["pore_pressure_p99_time_s"] = p99_time_s;
}

} // namespace mpm
