#include <setup/mpm_run_estimate.hpp>
#include <setup/mpm_state_bounds.hpp>

#include <algorithm>
#include <cmath>

namespace mpm
{
namespace
{
//! The largest |f(t)| of a time function (1 without one).
double largestFactor( const TimeFunction& f )
{
    double largest = f.empty() ? 1.0 : 0.0;
    for ( const auto& point : f )
        largest = std::max( largest, std::abs( point[1] ) );
    return largest;
}

} // namespace

//---------------------------------------------------------------------------//
Impl::StateBounds stateBounds( const CaseConfig& config )
{
    Impl::StateBounds bounds;
    bounds.max_speed_m_per_s = config.solver.instability_speed_factor *
                               estimateRun( config ).max_wave_speed_m_per_s;

    const GridConfig& g = config.grid;
    const double width = g.cells[0] * g.cell_size_m;
    const double height = g.cells[1] * g.cell_size_m;
    bounds.max_volume_m3 = width * height;

    const bool water = config.analysis != AnalysisType::Dry;
    double stress = water ? config.water.bulk_modulus_pa : 0.0;
    double density = water ? config.water.density_kg_per_m3 : 0.0;
    const auto materials = [&]( const std::vector<MaterialConfig>& list )
    {
        for ( const MaterialConfig& m : list )
        {
            const double nu = m.poisson_ratio;
            stress =
                std::max( stress, m.youngs_modulus_pa * ( 1.0 - nu ) /
                                      ( ( 1.0 + nu ) * ( 1.0 - 2.0 * nu ) ) );
            density = std::max(
                { density, m.density_kg_per_m3, m.solid_density_kg_per_m3 } );
        }
    };
    materials( config.materials );
    double gravity = 0.0;
    for ( const StageConfig& stage : config.stages )
    {
        materials( stage.materials );
        gravity = std::max( gravity, std::hypot( stage.gravity_m_per_s2[0],
                                                 stage.gravity_m_per_s2[1] ) );
        for ( const PointLoad& load : stage.loads )
            stress = std::max(
                stress, std::hypot( load.traction_pa[0], load.traction_pa[1] ) *
                            largestFactor( load.time_function ) );
        for ( const PorePressureCondition& p : stage.pore_pressures )
            stress = std::max( stress, std::abs( p.pressure_pa ) *
                                           largestFactor( p.time_function ) );
    }
    for ( const BodyConfig& body : config.bodies )
        stress = std::max(
            stress,
            std::abs( body.initial_pore_pressure_pa ) +
                std::abs( body.initial_pore_pressure_gradient_pa_per_m ) *
                    ( std::abs( g.origin_m[1] ) + height ) );
    stress = std::max( stress, density * gravity * height );
    bounds.max_stress_pa = 1000.0 * stress;
    return bounds;
}

} // namespace mpm
