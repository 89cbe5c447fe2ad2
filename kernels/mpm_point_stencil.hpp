#ifndef MPM_POINT_STENCIL_HPP
#define MPM_POINT_STENCIL_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! The cell (ci, cj) of a point and the bilinear weights and gradients of
//! its 4 nodes, node k = (ci + (k & 1), cj + (k >> 1)).
struct PointStencil
{
    int ci, cj;
    double w[4], dwdx[4], dwdy[4];
};

/*!
  \brief The loop of the step's point kernels: calls body(p, stencil) for
  every active point p with the stencil of its cell (PointStencil), in
  parallel over the points. The body unpacks it as
  `const auto& [ci, cj, w, dwdx, dwdy] = stencil;`.
*/
template <class ExecSpace, class Body>
void forEachPointStencil( const char* label, const ExecSpace& exec_space,
                          const ParticleViews<ExecSpace>& pv,
                          const physics::GridGeometry& grid, const Body& body )
{
    const auto points = unmanaged( pv );
    Kokkos::parallel_for(
        label, Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( points.status_p( p ) != point_active )
                return;
            PointStencil stencil;
            grid.weights( points.x_p( p, 0 ), points.x_p( p, 1 ), stencil.ci,
                          stencil.cj, stencil.w, stencil.dwdx, stencil.dwdy );
            body( p, stencil );
        } );
}

} // namespace mpm

#endif // MPM_POINT_STENCIL_HPP
