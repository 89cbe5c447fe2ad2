#ifndef MPM_G2P_HPP
#define MPM_G2P_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Grid-to-particle velocity update with a FLIP/PIC blend,
  v_p <- flip (v_p + sum N dv_i) + (1 - flip) sum N v_i,
  and the point's displacement increment du_p = dt sum N v_i (applied to
  x_p after the stress update, so that the whole MUSL step uses the shape
  functions at the start-of-step positions).
*/
template <class ExecSpace>
void g2pVelocity( const ExecSpace& exec_space,
                  const ParticleViews<ExecSpace>& pv,
                  const GridViews<ExecSpace>& gv, const double dt,
                  const double flip_fraction )
{
    const auto grid = gv.geometry;
    const auto v_i = gv.v_i;
    const auto dv_i = gv.dv_i;
    const auto x_p = pv.x_p;
    const auto v_p = pv.v_p;
    const auto du_p = pv.du_p;
    const auto status_p = pv.status_p;

    Kokkos::parallel_for(
        "mpm::g2p_velocity",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            double v_pic[2] = { 0.0, 0.0 };
            double dv[2] = { 0.0, 0.0 };
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                for ( int d = 0; d < 2; ++d )
                {
                    v_pic[d] += w[k] * v_i( i, j, d );
                    dv[d] += w[k] * dv_i( i, j, d );
                }
            }
            for ( int d = 0; d < 2; ++d )
            {
                v_p( p, d ) = flip_fraction * ( v_p( p, d ) + dv[d] ) +
                              ( 1.0 - flip_fraction ) * v_pic[d];
                du_p( p, d ) = dt * v_pic[d];
            }
        } );
}

} // namespace mpm

#endif // MPM_G2P_HPP
