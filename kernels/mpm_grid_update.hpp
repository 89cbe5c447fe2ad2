#ifndef MPM_GRID_UPDATE_HPP
#define MPM_GRID_UPDATE_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
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
    const auto m_i = unmanaged( gv.m_i );
    const auto p_i = unmanaged( gv.p_i );
    const auto f_i = unmanaged( gv.f_i );
    const auto v_i = unmanaged( gv.v_i );
    const auto dv_i = unmanaged( gv.dv_i );
    const auto flags_i = unmanaged( gv.flags_i );
    const auto active_i = unmanaged( gv.active_i );
    const int ny1 = gv.geometry.ny + 1;

    Kokkos::parallel_for(
        "mpm::grid_update_dry",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, gv.num_active ),
        KOKKOS_LAMBDA( const int a ) {
            const int n = active_i( a );
            const int i = n / ny1;
            const int j = n % ny1;
            takeMassMomentumForce( sums, n, i, j, m_i, p_i, f_i );
            // Nodes touched with zero weight only carry no mass.
            if ( !( m_i( i, j ) > 0.0 ) )
                return;
            const int flags = flags_i( i, j );
            update( m_i( i, j ), p_i( i, j, 0 ), f_i( i, j, 0 ),
                    flags & node_fix_x, v_i( i, j, 0 ), dv_i( i, j, 0 ) );
            update( m_i( i, j ), p_i( i, j, 1 ), f_i( i, j, 1 ),
                    flags & node_fix_y, v_i( i, j, 1 ), dv_i( i, j, 1 ) );
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
    const auto m_i = unmanaged( gv.m_i );
    const auto p_i = unmanaged( gv.p_i );
    const auto v_i = unmanaged( gv.v_i );
    const auto flags_i = unmanaged( gv.flags_i );
    const auto active_i = unmanaged( gv.active_i );
    const int ny1 = gv.geometry.ny + 1;

    Kokkos::parallel_for(
        "mpm::remap_velocity",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, gv.num_active ),
        KOKKOS_LAMBDA( const int a ) {
            const int n = active_i( a );
            const int i = n / ny1;
            const int j = n % ny1;
            p_i( i, j, 0 ) = sums.take( n, 0 );
            p_i( i, j, 1 ) = sums.take( n, 1 );
            if ( !( m_i( i, j ) > 0.0 ) )
                return;
            double v_x = p_i( i, j, 0 ) / m_i( i, j );
            double v_y = p_i( i, j, 1 ) / m_i( i, j );
            physics::applyVelocityBC( flags_i( i, j ), v_x, v_y );
            v_i( i, j, 0 ) = v_x;
            v_i( i, j, 1 ) = v_y;
        } );
}

} // namespace mpm

#endif // MPM_GRID_UPDATE_HPP
