#ifndef MPM_POSITION_UPDATE_HPP
#define MPM_POSITION_UPDATE_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Moves the points by their displacement increment, x_p += du_p.
  Returns the smallest index of a point now outside the grid, or -1.
  With `remove_outside`, such points are marked removed instead and
  `num_removed` counts them. A non-finite position is not "outside": it is
  left for checkStability to report as an instability.
*/
template <class ExecSpace>
int updatePositions( const ExecSpace& exec_space,
                     const ParticleViews<ExecSpace>& pv,
                     const physics::GridGeometry& grid,
                     const bool remove_outside, int& num_removed )
{
    const auto x_p = pv.x_p;
    const auto du_p = pv.du_p;
    const auto status_p = pv.status_p;
    const int none = pv.size();
    int first_outside = none;
    int removed = 0;

    Kokkos::parallel_reduce(
        "mpm::update_positions",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, int& first, int& count ) {
            if ( status_p( p ) != point_active )
                return;
            x_p( p, 0 ) += du_p( p, 0 );
            x_p( p, 1 ) += du_p( p, 1 );
            int ci, cj;
            if ( !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) &&
                 Kokkos::Experimental::isfinite( x_p( p, 0 ) + x_p( p, 1 ) ) )
            {
                if ( remove_outside )
                {
                    status_p( p ) = point_removed;
                    ++count;
                }
                else if ( p < first )
                    first = p;
            }
        },
        Kokkos::Min<int>( first_outside ), Kokkos::Sum<int>( removed ) );
    num_removed = removed;
    return first_outside >= none ? -1 : first_outside;
}

} // namespace mpm

#endif // MPM_POSITION_UPDATE_HPP
