#ifndef MPM_G2P_HPP
#define MPM_G2P_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_p2g.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
//! Interpolated nodal velocity sum N v_i and increment sum N dv_i at a point.
template <class VectorView>
KOKKOS_INLINE_FUNCTION void
interpolateVelocity( const int ci, const int cj, const double w[4],
                     const VectorView& v_i, const VectorView& dv_i,
                     double v_pic[2], double dv[2] )
{
    v_pic[0] = v_pic[1] = dv[0] = dv[1] = 0.0;
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
}

//! FLIP/PIC blend v <- flip (v + dv) + (1 - flip) v_pic of one component.
KOKKOS_INLINE_FUNCTION double flipPicBlend( const double flip_fraction,
                                            const double v, const double dv,
                                            const double v_pic )
{
    return flip_fraction * ( v + dv ) + ( 1.0 - flip_fraction ) * v_pic;
}

/*!
  \brief Two-phase FLIP/PIC update of one velocity component. The solid:
  flipPicBlend. The water, with `relative` (solver.water_relative_flip): the
  solid's new velocity plus the seepage velocity w = v_w - v_s, of which
  the part the grid does not carry keeps `memory` of its FLIP update,
    w' = w_pic + memory (w + dw - w_pic),
  so the mixture takes the PIC share and the seepage is damped as the drag
  damps it, never faster than the FLIP share (physics::seepageMemory). The
  water's own blend, which is this with memory = flip_fraction, damped the
  seepage near impermeable boundaries (a Gardner column under rain of
  0.9 K_s ponded in its top cell). Else the water's own blend.
*/
KOKKOS_INLINE_FUNCTION void
twoPhaseBlend( const double flip_fraction, const bool relative,
               const double memory, double& v_s, const double dv_s,
               const double v_s_pic, double& v_w, const double dv_w,
               const double v_w_pic )
{
    const double v_s_new = flipPicBlend( flip_fraction, v_s, dv_s, v_s_pic );
    if ( relative )
    {
        const double w_pic = v_w_pic - v_s_pic;
        const double w_flip = ( v_w + dv_w ) - ( v_s + dv_s );
        v_w = v_s_new + w_pic + memory * ( w_flip - w_pic );
    }
    else
        v_w = flipPicBlend( flip_fraction, v_w, dv_w, v_w_pic );
    v_s = v_s_new;
}

//! FLIP/PIC update of point p's velocity v_p from the nodal v_i, dv_i of
//! its cell; du_p (if given) gets the displacement increment dt sum N v_i.
template <class PointVectorView, class VectorView>
KOKKOS_INLINE_FUNCTION void
g2pPoint( const int p, const int ci, const int cj, const double w[4],
          const VectorView& v_i, const VectorView& dv_i,
          const double flip_fraction, const PointVectorView& v_p,
          const double dt, const PointVectorView& du_p )
{
    double v_pic[2], dv[2];
    interpolateVelocity( ci, cj, w, v_i, dv_i, v_pic, dv );
    for ( int d = 0; d < 2; ++d )
    {
        v_p( p, d ) =
            flipPicBlend( flip_fraction, v_p( p, d ), dv[d], v_pic[d] );
        if ( du_p.data() )
            du_p( p, d ) = dt * v_pic[d];
    }
}

//---------------------------------------------------------------------------//
/*!
  \brief Grid-to-particle update and MUSL remap scatter in one point loop:
  the FLIP/PIC blend
  v_p <- flip (v_p + sum N dv_i) + (1 - flip) sum N v_i
  and the displacement increment du_p = dt sum N v_i (applied to x_p in
  the last point loop, so that the whole MUSL step uses the shape
  functions at the start-of-step positions), then the updated momentum
  m_p v_p into `sums` (the points have not moved, so they touch the nodes
  of the step's P2G).
*/
template <class ExecSpace, class Duplication>
void g2pVelocityRemap( const ExecSpace& exec_space,
                       const ParticleViews<ExecSpace>& pv,
                       const GridViews<ExecSpace>& gv, const double dt,
                       const double flip_fraction,
                       const GridScatter<ExecSpace, 2, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    const auto grid = gv.geometry;
    const int ny1 = grid.ny + 1;
    const auto nodes = unmanaged( gv );
    const auto points = unmanaged( pv );

    forEachPointStencil(
        "mpm::g2p_velocity_remap", exec_space, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            g2pPoint( p, ci, cj, w, nodes.v_i, nodes.dv_i, flip_fraction,
                      points.v_p, dt, points.du_p );
            scatterPointMomentum( sums.access(), ci, cj, ny1, w,
                                  points.m_p( p ), points.v_p( p, 0 ),
                                  points.v_p( p, 1 ) );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Two-phase grid-to-particle update and MUSL remap scatter in one
  point loop: the FLIP/PIC blend of both phases (twoPhaseBlend; du_p as
  g2pVelocityRemap), then both phases' updated momenta
  into `sums` (mv_s x, y; mv_w x, y), with the water mass
  m_w = n S rho_w V of the point.
*/
template <class ExecSpace, class Duplication>
void g2pVelocityRemapTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg, const double dt,
    const double flip_fraction, const bool relative_flip,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double inertia_scaling,
    const GridScatter<ExecSpace, 4, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    const auto grid = gv.geometry;
    const int ny1 = grid.ny + 1;
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );

    forEachPointStencil(
        "mpm::g2p_velocity_remap_two_phase", exec_space, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            double v_s_pic[2], dv_s[2], v_w_pic[2], dv_w[2];
            interpolateVelocity( ci, cj, w, nodes.v_i, nodes.dv_i, v_s_pic,
                                 dv_s );
            interpolateVelocity( ci, cj, w, water_nodes.v_w_i,
                                 water_nodes.dv_w_i, v_w_pic, dv_w );
            const double n = water_points.n_p( p );
            const double S = water_points.S_p( p );
            // Only the relative blend uses it (an exp per point).
            const double memory =
                relative_flip
                    ? physics::seepageMemory(
                          dt, n, S,
                          materials[points.material_p( p )].permeability,
                          water_points.k_rel_p( p ), water.viscosity,
                          water.density, inertia_scaling, flip_fraction )
                    : 0.0;
            const auto v_s_p = points.v_p;
            const auto v_w_p = water_points.v_w_p;
            for ( int d = 0; d < 2; ++d )
            {
                twoPhaseBlend( flip_fraction, relative_flip, memory,
                               v_s_p( p, d ), dv_s[d], v_s_pic[d],
                               v_w_p( p, d ), dv_w[d], v_w_pic[d] );
                points.du_p( p, d ) = dt * v_s_pic[d];
            }
            const double m_w = n * S * water.density * points.vol_p( p );
            const auto node = sums.access();
            scatterPointMomentum( node, ci, cj, ny1, w, points.m_p( p ),
                                  v_s_p( p, 0 ), v_s_p( p, 1 ), 0 );
            scatterPointMomentum( node, ci, cj, ny1, w, m_w, v_w_p( p, 0 ),
                                  v_w_p( p, 1 ), 2 );
        } );
}

} // namespace mpm

#endif // MPM_G2P_HPP
