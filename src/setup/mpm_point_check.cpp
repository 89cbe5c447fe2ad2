#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_point_check.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpm
{
//---------------------------------------------------------------------------//
std::vector<std::string> pointRefusals( const CaseConfig& config )
{
    std::vector<std::string> refusals;
    const InitialPoints points = generatePoints( config );
    if ( points.size() == 0 )
    {
        refusals.push_back(
            "bodies: expected material points inside the body polygons, "
            "found none (every polygon is thinner than the spacing of "
            "grid.cell_size_m / particles.points_per_cell); enlarge the "
            "polygons or refine the grid" );
        return refusals;
    }
    for ( std::size_t k = 0; k < config.probes.points.size(); ++k )
    {
        const ProbeConfig& probe = config.probes.points[k];
        double best = std::numeric_limits<double>::infinity();
        for ( int p = 0; p < points.size(); ++p )
            best = std::min(
                best, std::hypot( points.x[2 * p] - probe.position_m[0],
                                  points.x[2 * p + 1] - probe.position_m[1] ) );
        if ( best > config.grid.cell_size_m )
            refusals.push_back(
                "key 'probes.points[" + std::to_string( k ) +
                "].position_m': expected a point in the soil (within one "
                "cell, " +
                std::to_string( config.grid.cell_size_m ) +
                " m, of a material point), found the probe '" + probe.name +
                "' " + std::to_string( best ) +
                " m from the nearest point; move it inside a body" );
    }
    return refusals;
}

} // namespace mpm
