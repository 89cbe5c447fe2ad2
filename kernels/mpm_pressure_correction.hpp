#ifndef MPM_PRESSURE_CORRECTION_HPP
#define MPM_PRESSURE_CORRECTION_HPP

#include <mpm_grid_views.hpp>
#include <mpm_node_force_response.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The nodal forces at node (i, j) of the cells' pressure increments
  dp_c (docs/formulation.md §9, item 2), as step 1 forms those of p_w: each
  point with a free p_w takes its cell's dp_c (a prescribed point, none),
  so the water force per unit water volume fraction is sum_p dp_p V grad N
  = sum_c dp_c g_c and the mixture force of Bishop's total stress sum_p S
  dp_p V grad N = sum_c dp_c g_S_c, over the node's (up to) 4 cells
  (pressurePointTerms' sums of the same points). dp_c is 0 off the
  unknowns.
*/
template <class CellView, class GradientView>
KOKKOS_INLINE_FUNCTION void
pressureIncrementForces( const int i, const int j, const int nx, const int ny,
                         const CellView& dp_c, const GradientView& g_c,
                         const GradientView& g_S_c, double f_w[2],
                         double f_m[2] )
{
    f_w[0] = f_w[1] = f_m[0] = f_m[1] = 0.0;
    for ( int b = 0; b < 2; ++b )
        for ( int a = 0; a < 2; ++a )
        {
            const int ci = i - a, cj = j - b;
            if ( ci < 0 || ci >= nx || cj < 0 || cj >= ny )
                continue;
            const double dp = dp_c( ci, cj );
            const int k = a + 2 * b; // node (i, j) in cell (ci, cj)
            for ( int d = 0; d < 2; ++d )
            {
                f_w[d] += dp * g_c( ci, cj, 2 * k + d );
                f_m[d] += dp * g_S_c( ci, cj, 2 * k + d );
            }
        }
}

//---------------------------------------------------------------------------//
/*!
  \brief Adds the velocity corrections of the pressure increment's forces
  (pressureIncrementForces) to the nodal velocities and increments of both
  phases: step 2's drag solve (physics::TwoPhaseNodalUpdate, with the
  node's masses, drag, flags and ties, no damping) on the forces alone.
  The solve is linear in the forces, so this equals solving step 2 again
  with them added, i.e. with p_w + dp at the points.
*/
template <class ExecSpace>
void correctNodalVelocities(
    const ExecSpace& exec, GridViews<ExecSpace>& gv,
    WaterGridViews<ExecSpace>& wg, const PressurePointTerms<ExecSpace>& terms,
    const Kokkos::View<double**, DeviceType<ExecSpace>>& dp_c, const double dt,
    const double water_viscosity, const double inertia_scaling,
    const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i )
{
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto flux_i = unmanaged( inflow_flux_i );
    const auto dp = unmanaged( dp_c );
    const auto g = unmanaged( terms.g_c );
    const auto g_S = unmanaged( terms.g_S_c );
    const int nx = gv.geometry.nx, ny = gv.geometry.ny;
    const physics::TwoPhaseNodalUpdate update{ dt, 0.0, inertia_scaling };
    forEachActiveNode(
        "mpm::pressure_correction", exec, gv,
        KOKKOS_LAMBDA( const int, const int i, const int j ) {
            if ( !( nodes.m_i( i, j ) > 0.0 ) )
                return;
            double f_w[2], f_m[2];
            pressureIncrementForces( i, j, nx, ny, dp, g, g_S, f_w, f_m );
            const NodeForceResponse node = nodeForceResponse(
                nodes, water_nodes, flux_i, i, j, update, water_viscosity );
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
