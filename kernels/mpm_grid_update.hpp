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
  \brief Compacts the nodes that carry mass into gv.active_i, so the grid
  update and the remap touch only nodes of cells with material points.
*/
template <class ExecSpace>
void findActiveNodes( const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
                      const double mass_tolerance = 0.0 )
{
    const auto m_i = unmanaged( gv.m_i );
    const auto active_i = unmanaged( gv.active_i );
    const int ny1 = gv.geometry.ny + 1;
    int num_active = 0;
    Kokkos::parallel_scan(
        "mpm::find_active_nodes",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, gv.geometry.numNodes() ),
        KOKKOS_LAMBDA( const int n, int& offset, const bool final ) {
            if ( m_i( n / ny1, n % ny1 ) > mass_tolerance )
            {
                if ( final )
                    active_i( offset ) = n;
                ++offset;
            }
        },
        num_active );
    gv.num_active = num_active;
}

//---------------------------------------------------------------------------//
/*!
  \brief Grid update of the dry (single-phase) step on the active nodes:
  new velocity v_i and its increment dv_i from momentum and force, with
  local damping and the nodes' boundary flags.
*/
template <class ExecSpace>
void gridUpdateDry( const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
                    const double dt, const double damping,
                    const double inertia_scaling = 1.0 )
{
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
            const int i = active_i( a ) / ny1;
            const int j = active_i( a ) % ny1;
            const int flags = flags_i( i, j );
            update( m_i( i, j ), p_i( i, j, 0 ), f_i( i, j, 0 ),
                    flags & node_fix_x, v_i( i, j, 0 ), dv_i( i, j, 0 ) );
            update( m_i( i, j ), p_i( i, j, 1 ), f_i( i, j, 1 ),
                    flags & node_fix_y, v_i( i, j, 1 ), dv_i( i, j, 1 ) );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief MUSL: nodal velocity from the remapped momentum, v_i = p_i / m_i,
  with the boundary flags applied, on the active nodes.
*/
template <class ExecSpace>
void remapVelocity( const ExecSpace& exec_space, GridViews<ExecSpace>& gv )
{
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
            const int i = active_i( a ) / ny1;
            const int j = active_i( a ) % ny1;
            double v_x = p_i( i, j, 0 ) / m_i( i, j );
            double v_y = p_i( i, j, 1 ) / m_i( i, j );
            physics::applyVelocityBC( flags_i( i, j ), v_x, v_y );
            v_i( i, j, 0 ) = v_x;
            v_i( i, j, 1 ) = v_y;
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The time loop's dry grid update: lists the nodes the P2G scatter
  touched into gv.active_i, takes their sums into gv.m_i, gv.p_i, gv.f_i
  and updates v_i and dv_i on those with mass, as gridUpdateDry.
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
  \brief The time loop's MUSL remap on the nodes of gv.active_i: takes the
  remapped momentum into gv.p_i and sets v_i = p_i / m_i with the boundary
  flags where there is mass, as remapVelocity.
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
