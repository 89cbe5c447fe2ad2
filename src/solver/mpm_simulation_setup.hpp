#ifndef MPM_SIMULATION_SETUP_HPP
#define MPM_SIMULATION_SETUP_HPP

#include <io/mpm_case_config.hpp>
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
                          WaterParticleViews<ExecSpace>& wv,
                          const physics::WaterParams& water )
{
    const physics::MaterialTable table = makeMaterialTable( config.materials );
    const bool two_phase = config.analysis != AnalysisType::Dry;
    auto x_h = Kokkos::create_mirror_view( pv.x_p );
    auto m_h = Kokkos::create_mirror_view( pv.m_p );
    auto vol_h = Kokkos::create_mirror_view( pv.vol_p );
    auto material_h = Kokkos::create_mirror_view( pv.material_p );
    auto id_h = Kokkos::create_mirror_view( pv.id_p );
    auto status_h = Kokkos::create_mirror_view( pv.status_p );
    for ( int p = 0; p < points.size(); ++p )
    {
        const MaterialConfig& material = config.materials[points.material[p]];
        x_h( p, 0 ) = points.x[2 * p];
        x_h( p, 1 ) = points.x[2 * p + 1];
        vol_h( p ) = points.vol[p];
        material_h( p ) = points.material[p];
        m_h( p ) = two_phase
                       ? ( 1.0 - material.porosity ) *
                             material.solid_density_kg_per_m3 * points.vol[p]
                       : material.density_kg_per_m3 * points.vol[p];
        id_h( p ) = p;
        status_h( p ) = point_active;
    }
    Kokkos::deep_copy( pv.x_p, x_h );
    Kokkos::deep_copy( pv.x0_p, x_h );
    Kokkos::deep_copy( pv.m_p, m_h );
    Kokkos::deep_copy( pv.vol_p, vol_h );
    Kokkos::deep_copy( pv.vol0_p, vol_h );
    Kokkos::deep_copy( pv.material_p, material_h );
    Kokkos::deep_copy( pv.id_p, id_h );
    Kokkos::deep_copy( pv.status_p, status_h );
    if ( !two_phase )
        return;

    auto p_w_h = Kokkos::create_mirror_view( wv.p_w_p );
    auto S_h = Kokkos::create_mirror_view( wv.S_p );
    auto dS_h = Kokkos::create_mirror_view( wv.dS_dp_p );
    auto k_rel_h = Kokkos::create_mirror_view( wv.k_rel_p );
    auto n_h = Kokkos::create_mirror_view( wv.n_p );
    for ( int p = 0; p < points.size(); ++p )
    {
        const double p_w = initialPorePressure( config.bodies[points.body[p]],
                                                points.x[2 * p + 1] );
        const physics::MaterialParams& params = table[points.material[p]];
        physics::RetentionState state{ 1.0, 0.0, 1.0 };
        if ( config.analysis == AnalysisType::Unsaturated )
            state = physics::Retention{}( params.retention, p_w );
        p_w_h( p ) = p_w;
        S_h( p ) = state.S;
        dS_h( p ) = state.dS_dp;
        k_rel_h( p ) = state.k_rel;
        n_h( p ) = config.materials[points.material[p]].porosity;
    }
    Kokkos::deep_copy( wv.p_w_p, p_w_h );
    Kokkos::deep_copy( wv.p_w_held_p, p_w_h );
    Kokkos::deep_copy( wv.S_p, S_h );
    Kokkos::deep_copy( wv.dS_dp_p, dS_h );
    Kokkos::deep_copy( wv.k_rel_p, k_rel_h );
    Kokkos::deep_copy( wv.n_p, n_h );
    Kokkos::deep_copy( wv.p_w_condition_p, -1 );
    Kokkos::deep_copy( wv.inflow_p, -1 );
    Kokkos::deep_copy( wv.inflow_weight_p, 1.0 );
    (void)water;
}

} // namespace mpm

#endif // MPM_SIMULATION_SETUP_HPP
