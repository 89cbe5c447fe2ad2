#ifndef MPM_GRID_UPDATE_HPP
#define MPM_GRID_UPDATE_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_p2g.hpp>
#include <physics/mpm_nodal_update.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Grid update of the dry (single-phase) step: lists the nodes the
  P2G scatter touched into gv.active_i, takes their sums into gv.m_i,
  gv.p_i, gv.f_i and, on those with mass, sets the new velocity v_i and
  its increment dv_i from momentum and force, with local damping and the
  nodes' boundary flags (physics::DryNodalUpdate).
*/
template <class ExecSpace, class Duplication>
void gridUpdateDry(
    const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
    const GridScatter<ExecSpace, DryNodeField::count, Duplication>& scatter,
    const double dt, const double damping, const double inertia_scaling )
{
    const auto sums = scatter.handle();
    gv.num_active = scatter.listTouched( exec_space, gv.active_i );
    const physics::DryNodalUpdate update{ dt, damping, inertia_scaling };
    const auto nodes = unmanaged( gv );

    forEachActiveNode(
        "mpm::grid_update_dry", exec_space, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            takeMassMomentumForce( sums, n, i, j, nodes.m_i, nodes.p_i,
                                   nodes.f_i );
            // Nodes touched with zero weight only carry no mass.
            const double m = nodes.m_i( i, j );
            if ( !( m > 0.0 ) )
                return;
            const int flags = nodes.flags_i( i, j );
            for ( int d = 0; d < 2; ++d )
                update( m, nodes.p_i( i, j, d ), nodes.f_i( i, j, d ),
                        flags & ( d == 0 ? node_fix_x : node_fix_y ),
                        nodes.v_i( i, j, d ), nodes.dv_i( i, j, d ) );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief MUSL remap on the nodes of gv.active_i: takes the remapped
  momentum into gv.p_i and sets v_i = p_i / m_i with the boundary flags
  where there is mass.
*/
template <class ExecSpace, class Duplication>
void remapVelocity( const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
                    const GridScatter<ExecSpace, 2, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    const auto nodes = unmanaged( gv );

    forEachActiveNode(
        "mpm::remap_velocity", exec_space, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            nodes.p_i( i, j, 0 ) = sums.take( n, 0 );
            nodes.p_i( i, j, 1 ) = sums.take( n, 1 );
            const double m = nodes.m_i( i, j );
            if ( !( m > 0.0 ) )
                return;
            double v_x = nodes.p_i( i, j, 0 ) / m;
            double v_y = nodes.p_i( i, j, 1 ) / m;
            physics::applyVelocityBC( nodes.flags_i( i, j ), v_x, v_y );
            nodes.v_i( i, j, 0 ) = v_x;
            nodes.v_i( i, j, 1 ) = v_y;
        } );
}

} // namespace mpm

#endif // MPM_GRID_UPDATE_HPP
