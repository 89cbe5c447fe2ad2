#include <solver/mpm_metrics.hpp>

#include <mpm_device_type.hpp>

#include <algorithm>
#include <cmath>

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

nlohmann::json stageMetrics( const StageSummary& stage )
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
    return j;
}

} // namespace mpm
