#ifndef MPM_P2G_HPP
#define MPM_P2G_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_scatter.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the dry P2G sums of a node.
struct DryNodeField
{
    enum : int
    {
        m,
        p_x,
        p_y,
        f_x,
        f_y,
        count
    };
};

//! Nodal sums of the dry P2G scatter.
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
using DryNodeSums = GridScatter<ExecSpace, DryNodeField::count, Duplication>;

//! Nodal sums of a momentum remap (p_x, p_y).
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
using MomentumSums = GridScatter<ExecSpace, 2, Duplication>;

//---------------------------------------------------------------------------//
/*!
  \brief Particle-to-grid scatter of mass, momentum and force into `sums`
  (DryNodeField), touching the 4 nodes of every active point:
  m_i = sum N m_p, p_i = sum N m_p v_p,
  f_i = sum N (m_p g + load) - sum vol_p sigma_p . grad N.
  `load_force(l, d)` is the force (N) on a point of load l; points with
  load_p < 0 carry none.
*/
template <class ExecSpace, class Duplication, class LoadView>
void scatterMassMomentumForce(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const physics::GridGeometry& grid, const double gravity_x,
    const double gravity_y, const LoadView& load_force,
    const GridScatter<ExecSpace, DryNodeField::count, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    using F = DryNodeField;
    const int ny1 = grid.ny + 1;
    const auto points = unmanaged( pv );
    const auto loads = unmanaged( load_force );

    forEachPointStencil(
        "mpm::p2g_mass_momentum_force", exec_space, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            const double m = points.m_p( p );
            const double vol = points.vol_p( p );
            const double s_xx = points.sigma_p( p, 0 );
            const double s_yy = points.sigma_p( p, 1 );
            const double s_xy = points.sigma_p( p, 2 );
            const int load = points.load_p( p );
            const double f_x =
                m * gravity_x + ( load >= 0 ? loads( load, 0 ) : 0.0 );
            const double f_y =
                m * gravity_y + ( load >= 0 ? loads( load, 1 ) : 0.0 );
            const auto node = sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int n = nodeIndex( ci + ( k & 1 ), cj + ( k >> 1 ), ny1 );
                node.touch( n );
                node.add( n, F::m, w[k] * m );
                node.add( n, F::p_x, w[k] * m * points.v_p( p, 0 ) );
                node.add( n, F::p_y, w[k] * m * points.v_p( p, 1 ) );
                node.add( n, F::f_x,
                          w[k] * f_x -
                              vol * ( s_xx * dwdx[k] + s_xy * dwdy[k] ) );
                node.add( n, F::f_y,
                          w[k] * f_y -
                              vol * ( s_xy * dwdx[k] + s_yy * dwdy[k] ) );
            }
        } );
}

//---------------------------------------------------------------------------//
//! Takes the dry P2G sums of node n = (i, j) into m_i, p_i and f_i.
template <class Sums, class ScalarView, class VectorView>
KOKKOS_INLINE_FUNCTION void
takeMassMomentumForce( const Sums& sums, const int n, const int i, const int j,
                       const ScalarView& m_i, const VectorView& p_i,
                       const VectorView& f_i )
{
    using F = DryNodeField;
    m_i( i, j ) = sums.take( n, F::m );
    p_i( i, j, 0 ) = sums.take( n, F::p_x );
    p_i( i, j, 1 ) = sums.take( n, F::p_y );
    f_i( i, j, 0 ) = sums.take( n, F::f_x );
    f_i( i, j, 1 ) = sums.take( n, F::f_y );
}

//---------------------------------------------------------------------------//
//! MUSL remap scatter of one point's momentum, p_i += N m_p v_p, into
//! fields (field, field + 1) of its 4 nodes.
template <class Access>
KOKKOS_INLINE_FUNCTION void
scatterPointMomentum( const Access& node, const int ci, const int cj,
                      const int ny1, const double w[4], const double m,
                      const double v_x, const double v_y, const int field = 0 )
{
    for ( int k = 0; k < 4; ++k )
    {
        const int n = nodeIndex( ci + ( k & 1 ), cj + ( k >> 1 ), ny1 );
        node.add( n, field, w[k] * m * v_x );
        node.add( n, field + 1, w[k] * m * v_y );
    }
}

} // namespace mpm

#endif // MPM_P2G_HPP
