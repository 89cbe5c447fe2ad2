#include <setup/mpm_conditions.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <setup/mpm_point_check.hpp>

#include <mpm_status_flags.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpm
{
namespace
{
//! "key 'stages[s].<list>[k].where': ..." for every selection of the
//! stages that picks none of the points at x.
std::vector<std::string> emptySelections( const CaseConfig& config,
                                          const std::vector<double>& x )
{
    std::vector<std::string> warnings;
    const std::vector<int> status( x.size() / 2, point_active );
    for ( std::size_t s = 0; s < config.stages.size(); ++s )
    {
        const StageConfig& stage = config.stages[s];
        const auto check = [&]( const char* list, const std::size_t k,
                                const PointSelection& selection )
        {
            const auto picked =
                selectPoints( selection, x, status, config.grid );
            if ( std::find( picked.begin(), picked.end(), true ) ==
                 picked.end() )
                warnings.push_back(
                    "key 'stages[" + std::to_string( s ) + "]." + list + "[" +
                    std::to_string( k ) +
                    "].where': selects no material point at the points' "
                    "initial positions (the run checks again at the stage "
                    "start)" );
        };
        for ( std::size_t k = 0; k < stage.loads.size(); ++k )
            check( "loads", k, stage.loads[k].points );
        for ( std::size_t k = 0; k < stage.pore_pressures.size(); ++k )
            check( "pore_pressures", k, stage.pore_pressures[k].points );
        for ( std::size_t k = 0; k < stage.inflows.size(); ++k )
            check( "inflows", k, stage.inflows[k].points );
    }
    return warnings;
}
} // namespace

//---------------------------------------------------------------------------//
std::vector<std::string> pointRefusals( const CaseConfig& config )
{
    return checkPoints( config ).refusals;
}

//---------------------------------------------------------------------------//
PointFindings checkPoints( const CaseConfig& config )
{
    PointFindings findings;
    std::vector<std::string>& refusals = findings.refusals;
    const InitialPoints points = generatePoints( config );
    if ( points.size() == 0 )
    {
        refusals.push_back(
            "bodies: expected material points inside the body polygons, "
            "found none (every polygon is thinner than the spacing of "
            "grid.cell_size_m / particles.points_per_cell); enlarge the "
            "polygons or refine the grid" );
        return findings;
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
    findings.warnings = emptySelections( config, points.x );
    return findings;
}

} // namespace mpm
