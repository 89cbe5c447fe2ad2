#ifndef MPM_NODE_LOOP_HPP
#define MPM_NODE_LOOP_HPP

#include <mpm_grid_views.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
/*!
  \brief The loop of the step's node kernels: calls body(n, i, j) for
  every node of gv.active_i (the nodes the step's P2G touched), n its flat
  index i * (ny + 1) + j, in parallel over the nodes.
*/
template <class ExecSpace, class Body>
void forEachActiveNode( const char* label, const ExecSpace& exec_space,
                        const GridViews<ExecSpace>& gv, const Body& body )
{
    const auto active_i = unmanaged( gv.active_i );
    const int ny1 = gv.geometry.ny + 1;
    Kokkos::parallel_for(
        label, Kokkos::RangePolicy<ExecSpace>( exec_space, 0, gv.num_active ),
        KOKKOS_LAMBDA( const int a ) {
            const int n = active_i( a );
            body( n, n / ny1, n % ny1 );
        } );
}

} // namespace mpm

#endif // MPM_NODE_LOOP_HPP
