#ifndef MPM_PRESSURE_OPERATOR_HPP
#define MPM_PRESSURE_OPERATOR_HPP

#include <mpm_grid_views.hpp>
#include <mpm_node_force_response.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The mobility mu_I,d of each active node along x and y
  (docs/formulation.md §9, item 3): the water volume rate
  n S dv_w + (1 - n) S dv_s that step 2's drag solve (physics::
  TwoPhaseNodalUpdate, the node's masses, drag, flags and ties) gives the
  forces of a unit pressure gradient, n S on the water and S on the
  mixture (Bishop's share), with the node's n S = m_w / (rho_w V) and its
  S the points' volume-weighted mean (pressurePointTerms' node sums, taken
  here). m^3 s / kg per m^2 of gradient force: K = G^T mu G.
*/
template <class ExecSpace>
void pressureNodeMobility(
    const ExecSpace& exec, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg, const PressurePointTerms<ExecSpace>& t,
    const double dt, const double water_viscosity, const double inertia_scaling,
    const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i,
    const Kokkos::View<double** [2], DeviceType<ExecSpace>>& mu_i )
{
    using N = PressureNodeField;
    const auto sums = t.node_sums.handle();
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto flux_i = unmanaged( inflow_flux_i );
    const auto mu = unmanaged( mu_i );
    const physics::TwoPhaseNodalUpdate update{ dt, 0.0, inertia_scaling };
    forEachActiveNode(
        "mpm::pressure_node_mobility", exec, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            const double volume = sums.take( n, N::volume );
            const double saturation = sums.take( n, N::saturation );
            mu( i, j, 0 ) = mu( i, j, 1 ) = 0.0;
            if ( !( nodes.m_i( i, j ) > 0.0 ) || !( volume > 0.0 ) )
                return;
            const NodeForceResponse node = nodeForceResponse(
                nodes, water_nodes, flux_i, i, j, update, water_viscosity );
            const double S = saturation / volume;
            const double nS = node.water.nS;
            for ( int d = 0; d < 2; ++d )
            {
                const auto r = node.along( d, S, nS );
                mu( i, j, d ) = nS * r.v_w + ( S - nS ) * r.v_s;
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The flow part of the pressure equation over the cells
  (docs/formulation.md §9, item 3), into s.a (a 9-point stencil over the
  nx x ny cells), and its unknowns into s.nodes (flat cell indices
  ci ny + cj, increasing): the cells with a free point and storage.
  K = G^T mu G, K_cc' = sum over the nodes I the cells share, sum_d
  g_cI,d mu_I,d g_c'I,d: the water the corrected velocities carry out of
  cell c per pascal of increment in c'. Plus the checkerboard penalty:
  G has the checkerboard of cell pressures in its null space (equal-order
  bilinear velocities, constant pressures), so at each node whose 4 cells
  are all unknowns it adds (tau / 2) v v^T, v = (+1, -1, -1, +1) the
  checkerboard of those cells, tau = h^2 (mu_x + mu_y) / 2. It conserves
  water (v sums to 0), is 2 tau (1 - cos a)(1 - cos b) on a Fourier mode
  (a 4th difference: O(h^4) on a smooth field) and, on a uniform block,
  turns K's stencil (2 tau; corners -tau / 2) into the 5-point one
  (4 tau; faces -tau).
*/
template <class ExecSpace>
void assemblePressureOperator(
    const ExecSpace& exec, const physics::GridGeometry& grid,
    const PressurePointTerms<ExecSpace>& t,
    const Kokkos::View<double** [2], DeviceType<ExecSpace>>& mu_i,
    NodeStencilSystem<ExecSpace>& s )
{
    const int nx = grid.nx, ny = grid.ny;
    const double h = grid.h;
    const auto g = unmanaged( t.g_c );
    const auto storage = unmanaged( t.storage_c );
    const auto free_points = unmanaged( t.free_c );
    const auto mu = unmanaged( mu_i );
    const auto touched = unmanaged( t.touched_c );
    const auto a = unmanaged( s.a );
    const auto unknown = KOKKOS_LAMBDA( const int i, const int j )
    {
        return i >= 0 && i < nx && j >= 0 && j < ny &&
               isPressureUnknown( free_points, storage, i, j );
    };
    Kokkos::parallel_for(
        "mpm::pressure_operator",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, t.num_touched ),
        KOKKOS_LAMBDA( const int m ) {
            const int ci = touched( m ) / ny, cj = touched( m ) % ny;
            double row[9] = {};
            // Which of the 3 x 3 cells around (ci, cj) are unknowns: cell
            // (ci + di, cj + dj) at 3 (di + 1) + (dj + 1), as the row's slots.
            bool around[9];
            for ( int slot = 0; slot < 9; ++slot )
                around[slot] = unknown( ci + slot / 3 - 1, cj + slot % 3 - 1 );
            if ( around[4] )
                for ( int k = 0; k < 4; ++k )
                {
                    const int ni = ci + k % 2, nj = cj + k / 2;
                    // The 4 cells of node (ni, nj): (ni - 1 + q % 2,
                    // nj - 1 + q / 2), at slot 3 (k % 2 + q % 2) + k / 2 +
                    // q / 2 around (ci, cj); this one is q = 3 - k.
                    const auto slotOf = [k]( const int q )
                    { return 3 * ( k % 2 + q % 2 ) + k / 2 + q / 2; };
                    const bool block =
                        around[slotOf( 0 )] && around[slotOf( 1 )] &&
                        around[slotOf( 2 )] && around[slotOf( 3 )];
                    const double tau =
                        0.5 * h * h * ( mu( ni, nj, 0 ) + mu( ni, nj, 1 ) );
                    const double sign_here = k == 0 || k == 3 ? 1.0 : -1.0;
                    for ( int q = 0; q < 4; ++q )
                    {
                        const int slot = slotOf( q );
                        if ( !around[slot] )
                            continue;
                        const int oi = ni - 1 + q % 2, oj = nj - 1 + q / 2;
                        // Node (ni, nj) is corner 3 - q of cell (oi, oj).
                        const int kk = 3 - q;
                        for ( int d = 0; d < 2; ++d )
                            row[slot] += g( ci, cj, 2 * k + d ) *
                                         mu( ni, nj, d ) *
                                         g( oi, oj, 2 * kk + d );
                        if ( block )
                            row[slot] += 0.5 * tau * sign_here *
                                         ( q == 0 || q == 3 ? 1.0 : -1.0 );
                    }
                }
            for ( int k = 0; k < 9; ++k )
                a( ci, cj, k ) = row[k];
        } );
    const auto cells = unmanaged( s.nodes );
    int count = 0;
    Kokkos::parallel_scan(
        "mpm::pressure_unknowns",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, t.num_touched ),
        KOKKOS_LAMBDA( const int m, int& offset, const bool final ) {
            const int c = touched( m );
            if ( !unknown( c / ny, c % ny ) )
                return;
            if ( final )
                cells( offset ) = c;
            ++offset;
        },
        count );
    s.num_nodes = count;
}

} // namespace mpm

#endif // MPM_PRESSURE_OPERATOR_HPP
