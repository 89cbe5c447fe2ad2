#ifndef MPM_PRESSURE_CORRECTION_HPP
#define MPM_PRESSURE_CORRECTION_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_force_response.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the pressure increment's nodal forces.
struct PressureForceField
{
    enum : int
    {
        f_w_x, //!< water force per unit water volume fraction, N
        f_w_y,
        f_m_x, //!< mixture force (Bishop's share S dp), N
        f_m_y,
        count
    };
};

template <class ExecSpace>
using PressureForceSums = GridScatter<ExecSpace, PressureForceField::count>;

//---------------------------------------------------------------------------//
/*!
  \brief The nodal forces of the cells' pressure increments dp_c
  (docs/formulation.md §9, item 2), formed as step 1 forms those of p_w:
  each point with a free p_w takes its cell's dp_c (a point whose p_w is
  prescribed, none), the water force per unit water volume fraction
  sum_p dp_p V grad N and the mixture force of Bishop's total stress,
  sum_p S dp_p V grad N. So the corrected velocities are those step 2 gives
  with p_w + dp at the points.
*/
template <class ExecSpace, class CellView>
void scatterPressureForces( const ExecSpace& exec,
                            const ParticleViews<ExecSpace>& pv,
                            const WaterParticleViews<ExecSpace>& wv,
                            const physics::GridGeometry& grid,
                            const CellView& dp_c,
                            const PressureForceSums<ExecSpace>& forces )
{
    using F = PressureForceField;
    const auto sums = forces.handle();
    const auto vol_p = unmanaged( pv.vol_p );
    const auto S_p = unmanaged( wv.S_p );
    const auto condition_p = unmanaged( wv.p_w_condition_p );
    const auto dp = unmanaged( dp_c );
    forEachPointStencil(
        "mpm::pressure_forces", exec, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            if ( condition_p( p ) >= 0 )
                return;
            const double water = dp( ci, cj ) * vol_p( p );
            const double mixture = S_p( p ) * water;
            auto access = sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int node =
                    nodeIndex( ci + k % 2, cj + k / 2, grid.ny + 1 );
                access.add( node, F::f_w_x, water * dwdx[k] );
                access.add( node, F::f_w_y, water * dwdy[k] );
                access.add( node, F::f_m_x, mixture * dwdx[k] );
                access.add( node, F::f_m_y, mixture * dwdy[k] );
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Adds the velocity corrections of the pressure increment's forces
  (scatterPressureForces) to the nodal velocities and increments of both
  phases: step 2's drag solve (physics::TwoPhaseNodalUpdate, with the
  node's masses, drag, flags and ties, no damping) on the forces alone.
  The solve is linear in the forces, so this equals solving step 2 again
  with them added.
*/
template <class ExecSpace>
void correctNodalVelocities(
    const ExecSpace& exec, GridViews<ExecSpace>& gv,
    WaterGridViews<ExecSpace>& wg, const PressureForceSums<ExecSpace>& forces,
    const double dt, const double water_density, const double water_viscosity,
    const double inertia_scaling,
    const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i )
{
    using F = PressureForceField;
    const auto sums = forces.handle();
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto flux_i = unmanaged( inflow_flux_i );
    const physics::TwoPhaseNodalUpdate update{ dt, 0.0, inertia_scaling };
    forEachActiveNode(
        "mpm::pressure_correction", exec, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            double f_w[2], f_m[2];
            for ( int d = 0; d < 2; ++d )
            {
                f_w[d] = sums.take( n, F::f_w_x + d );
                f_m[d] = sums.take( n, F::f_m_x + d );
            }
            if ( !( nodes.m_i( i, j ) > 0.0 ) )
                return;
            const NodeForceResponse node =
                nodeForceResponse( nodes, water_nodes, flux_i, i, j, update,
                                   water_density, water_viscosity );
            for ( int d = 0; d < 2; ++d )
            {
                const auto r = node.along( d, f_m[d], node.water.nS * f_w[d] );
                nodes.v_i( i, j, d ) += r.v_s;
                nodes.dv_i( i, j, d ) += r.v_s;
                water_nodes.v_w_i( i, j, d ) += r.v_w;
                water_nodes.dv_w_i( i, j, d ) += r.v_w;
            }
        } );
}

} // namespace mpm

#endif // MPM_PRESSURE_CORRECTION_HPP
