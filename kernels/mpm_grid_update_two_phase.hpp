#ifndef MPM_GRID_UPDATE_TWO_PHASE_HPP
#define MPM_GRID_UPDATE_TWO_PHASE_HPP

#include <mpm_base_cells.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_p2g_two_phase.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_nodal_update.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Grid update of the two-phase step: lists the nodes the P2G
  scatter touched into gv.active_i, takes their sums into the grid fields
  (gv.m_i = solid mass, gv.p_i = solid momentum, gv.f_i = mixture force,
  and the WaterGridViews fields), then, on the nodes with solid mass, the
  new solid and water velocities with the drag implicit
  (TwoPhaseNodalUpdate), the solid's boundary flags and the water's
  impermeability ties; a component with a prescribed inward flux (flux_i,
  an inflow on a grid edge) is tied with that flux's seepage
  (physics::tiedSeepage). The water force (per unit water volume) is scaled
  by the nodal n S = m_w / (rho_w vol); the drag comes from the nodal mean
  permeability (physics::nodalWater). Nodes of base cells get the forces
  that complete those cells (BaseCellAccess::addNodeForces).
*/
template <class ExecSpace, class Duplication>
void gridUpdateTwoPhase(
    const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
    WaterGridViews<ExecSpace>& wg,
    const GridScatter<ExecSpace, TwoPhaseNodeField::count, Duplication>&
        scatter,
    const double dt, const double damping, const double water_density,
    const double water_viscosity, const double inertia_scaling,
    const BaseCellAccess<ExecSpace>& base,
    const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i )
{
    const auto sums = scatter.handle();
    using F = TwoPhaseNodeField;
    const int nx = gv.geometry.nx;
    gv.num_active = scatter.listTouched( exec_space, gv.active_i );
    const physics::TwoPhaseNodalUpdate update{ dt, damping, inertia_scaling };
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto flux_i = unmanaged( inflow_flux_i );

    forEachActiveNode(
        "mpm::grid_update_two_phase", exec_space, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            const double m_s = sums.take( n, F::m_s );
            const double m_w = sums.take( n, F::m_w );
            const double vol = sums.take( n, F::vol );
            const double q = sums.take( n, F::q );
            double mv_s[2], f_m[2], mv_w[2], f_w[2];
            for ( int d = 0; d < 2; ++d )
            {
                mv_s[d] = sums.take( n, F::mv_s_x + d );
                f_m[d] = sums.take( n, F::f_m_x + d );
                mv_w[d] = sums.take( n, F::mv_w_x + d );
                f_w[d] = sums.take( n, F::f_w_x + d );
            }
            base.addNodeForces( i, j, nx, f_m, f_w );
            for ( int d = 0; d < 2; ++d )
            {
                nodes.p_i( i, j, d ) = mv_s[d];
                nodes.f_i( i, j, d ) = f_m[d];
                water_nodes.mv_w_i( i, j, d ) = mv_w[d];
                water_nodes.f_w_i( i, j, d ) = f_w[d];
            }
            nodes.m_i( i, j ) = m_s;
            water_nodes.m_w_i( i, j ) = m_w;
            water_nodes.vol_i( i, j ) = vol;
            const double nS =
                m_w > 0.0 ? physics::waterFraction( m_w, vol, water_density )
                          : 0.0;
            water_nodes.nS_i( i, j ) = nS;
            water_nodes.q_i( i, j ) = q;
            // Nodes touched with zero weight only carry no mass.
            if ( !( m_s > 0.0 ) )
                return;

            const int flags = nodes.flags_i( i, j );
            const int flags_w = water_nodes.flags_w_i( i, j );
            const physics::NodalWater water =
                physics::nodalWater( nS, vol, q, water_viscosity );
            for ( int d = 0; d < 2; ++d )
            {
                const int bit = d == 0 ? node_fix_x : node_fix_y;
                const double flux = flux_i( i, j, d );
                const auto r =
                    update( m_s, m_w, mv_s[d], mv_w[d], f_m[d],
                            water.nS * f_w[d], water.drag, flags & bit,
                            water.locked || ( flags_w & bit ) || flux != 0.0,
                            physics::tiedSeepage( flux, m_w, m_s, vol,
                                                  water_density ) );
                nodes.v_i( i, j, d ) = r.v_s;
                nodes.dv_i( i, j, d ) = r.dv_s;
                water_nodes.v_w_i( i, j, d ) = r.v_w;
                water_nodes.dv_w_i( i, j, d ) = r.dv_w;
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief MUSL on the nodes of gv.active_i: takes the remapped momenta of
  both phases into gv.p_i and wg.mv_w_i and, where there is solid mass,
  the nodal velocities, with the solid's flags and the water ties
  (v_w = v_s + the seepage of a prescribed flux on tied components).
*/
template <class ExecSpace, class Duplication>
void remapVelocityTwoPhase(
    const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
    WaterGridViews<ExecSpace>& wg,
    const GridScatter<ExecSpace, 4, Duplication>& scatter,
    const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i,
    const double water_density )
{
    const auto sums = scatter.handle();
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto flux_i = unmanaged( inflow_flux_i );

    forEachActiveNode(
        "mpm::remap_velocity_two_phase", exec_space, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            double mv_s[2], mv_w[2];
            for ( int d = 0; d < 2; ++d )
            {
                mv_s[d] = nodes.p_i( i, j, d ) = sums.take( n, d );
                mv_w[d] = water_nodes.mv_w_i( i, j, d ) = sums.take( n, 2 + d );
            }
            const double m_s = nodes.m_i( i, j );
            if ( !( m_s > 0.0 ) )
                return;
            double v_s[2] = { mv_s[0] / m_s, mv_s[1] / m_s };
            physics::applyVelocityBC( nodes.flags_i( i, j ), v_s[0], v_s[1] );
            const int flags_w = water_nodes.flags_w_i( i, j );
            for ( int d = 0; d < 2; ++d )
            {
                const int bit = d == 0 ? node_fix_x : node_fix_y;
                const double flux = flux_i( i, j, d );
                nodes.v_i( i, j, d ) = v_s[d];
                water_nodes.v_w_i( i, j, d ) = physics::remappedWaterVelocity(
                    v_s[d], mv_w[d], water_nodes.m_w_i( i, j ), m_s,
                    ( flags_w & bit ) || flux != 0.0, flux,
                    water_nodes.vol_i( i, j ), water_density );
            }
        } );
}

} // namespace mpm

#endif // MPM_GRID_UPDATE_TWO_PHASE_HPP
