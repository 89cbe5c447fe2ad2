#ifndef MPM_SIMULATION_SETUP_HPP
#define MPM_SIMULATION_SETUP_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_retention.hpp>
#include <setup/mpm_conditions.hpp>
#include <setup/mpm_materials.hpp>
#include <setup/mpm_particle_generator.hpp>
#include <solver/mpm_stage_conditions.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <vector>

namespace mpm
{
//! Kernel-side grid geometry of a case.
inline physics::GridGeometry gridGeometry( const GridConfig& config )
{
    physics::GridGeometry g;
    g.x0 = config.origin_m[0];
    g.y0 = config.origin_m[1];
    g.h = config.cell_size_m;
    g.nx = config.cells[0];
    g.ny = config.cells[1];
    return g;
}

//! Kernel-side water constants of a case.
inline physics::WaterParams waterParams( const WaterConfig& config )
{
    return { config.density_kg_per_m3, config.bulk_modulus_pa,
             config.viscosity_pa_s };
}

//---------------------------------------------------------------------------//
/*!
  \brief Initial state of the points: positions, volumes, materials, ids;
  dry: mass = bulk density x volume; two-phase: mass = solid mass
  (1 - n0) rho_s V, porosity n0, pore pressure from the body's initial
  p_w(y) (initialPorePressure) and the retention state at it.
*/
template <class ExecSpace>
void initialiseParticles( const CaseConfig& config, const InitialPoints& points,
                          ParticleViews<ExecSpace>& pv,
                          WaterParticleViews<ExecSpace>& wv )
{
    using Host = Kokkos::DefaultHostExecutionSpace;
    const physics::MaterialTable table = makeMaterialTable( config.materials );
    const bool two_phase = config.analysis != AnalysisType::Dry;
    ParticleViews<Host> host( points.size() );
    WaterParticleViews<Host> water_host( two_phase ? points.size() : 0 );
    Kokkos::deep_copy( water_host.p_w_condition_p, -1 );
    Kokkos::deep_copy( water_host.inflow_p, -1 );
    Kokkos::deep_copy( water_host.inflow_weight_p, 1.0 );
    for ( int p = 0; p < points.size(); ++p )
    {
        const MaterialConfig& material = config.materials[points.material[p]];
        for ( int d = 0; d < 2; ++d )
            host.x_p( p, d ) = host.x0_p( p, d ) = points.x[2 * p + d];
        host.vol_p( p ) = host.vol0_p( p ) = points.vol[p];
        host.material_p( p ) = points.material[p];
        host.m_p( p ) = two_phase ? ( 1.0 - material.porosity ) *
                                        material.solid_density_kg_per_m3 *
                                        points.vol[p]
                                  : material.density_kg_per_m3 * points.vol[p];
        host.id_p( p ) = p;
        host.status_p( p ) = point_active;
        if ( !two_phase )
            continue;
        const double p_w = initialPorePressure( config.bodies[points.body[p]],
                                                points.x[2 * p + 1] );
        physics::RetentionState state{ 1.0, 0.0, 1.0 };
        if ( config.analysis == AnalysisType::Unsaturated )
            state = physics::Retention{}( table[points.material[p]].retention,
                                          p_w );
        water_host.p_w_p( p ) = water_host.p_w_held_p( p ) = p_w;
        water_host.S_p( p ) = state.S;
        water_host.dS_dp_p( p ) = state.dS_dp;
        water_host.k_rel_p( p ) = state.k_rel;
        water_host.n_p( p ) = material.porosity;
    }
    copyViews( host, pv );
    if ( two_phase )
        copyViews( water_host, wv );
}

} // namespace mpm

#endif // MPM_SIMULATION_SETUP_HPP
