#ifndef MPM_POSITION_UPDATE_HPP
#define MPM_POSITION_UPDATE_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Moves point p by its displacement increment, x_p += du_p, and
  returns true if it is now outside the grid. A non-finite position is not
  "outside": it is left for the stability check to report as an
  instability.
*/
template <class VectorView>
KOKKOS_INLINE_FUNCTION bool movePoint( const int p, const VectorView& x_p,
                                       const VectorView& du_p,
                                       const physics::GridGeometry& grid )
{
    x_p( p, 0 ) += du_p( p, 0 );
    x_p( p, 1 ) += du_p( p, 1 );
    int ci, cj;
    return !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) &&
           Kokkos::Experimental::isfinite( x_p( p, 0 ) + x_p( p, 1 ) );
}

} // namespace mpm

#endif // MPM_POSITION_UPDATE_HPP
