#ifndef MPM_P2G_TWO_PHASE_HPP
#define MPM_P2G_TWO_PHASE_HPP

#include <mpm_base_cells.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the two-phase P2G sums of a node.
struct TwoPhaseNodeField
{
    enum : int
    {
        m_s,    //!< solid mass, kg
        mv_s_x, //!< solid momentum, kg m/s
        mv_s_y,
        f_m_x, //!< mixture force, N
        f_m_y,
        m_w,    //!< water mass, kg
        vol,    //!< mixture volume, m^3
        mv_w_x, //!< water momentum, kg m/s
        mv_w_y,
        f_w_x, //!< water force per unit water volume fraction, N
        f_w_y,
        q, //!< permeability sum N k k_rel V, m^4
        count
    };
};

//! Nodal sums of the two-phase P2G scatter.
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
using TwoPhaseNodeSums =
    GridScatter<ExecSpace, TwoPhaseNodeField::count, Duplication>;

//! Nodal sums of the two-phase momentum remap (mv_s x, y; mv_w x, y).
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
using TwoPhaseMomentumSums = GridScatter<ExecSpace, 4, Duplication>;

//---------------------------------------------------------------------------//
/*!
  \brief Two-phase particle-to-grid scatter (formulation.md, step 1) into
  `sums` (TwoPhaseNodeField), touching the 4 nodes of every active point:
  solid mass and momentum, water mass and momentum, mixture force
  F_m = sum N rho_m V g - sum V sigma . grad N + loads with the total
  (Bishop) stress sigma = sigma' - S p_w m (Eq. 11), and the water
  momentum (Eq. 9) integrated per unit water volume:
  f_w = sum N rho_w V g + sum p_w V grad N (exact integration by parts of
  -grad p_w, no grad(nS) term lost), the permeability sum
  kv = sum N k k_rel V and vol = sum N V; the grid update forms the drag
  from the nodal mean permeability kv / vol and the nodal n S =
  m_w / (rho_w vol).
  `load_force` holds the force (N) on a point of each load condition.
  Points of base cells also go into their cell's sums (BaseCellAccess).
*/
template <class ExecSpace, class Duplication, class LoadView>
void scatterTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const physics::GridGeometry& grid,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double gravity_x, const double gravity_y, const LoadView& load_force,
    const GridScatter<ExecSpace, TwoPhaseNodeField::count, Duplication>&
        scatter,
    const BaseCellAccess<ExecSpace>& base )
{
    const auto sums = scatter.handle();
    using F = TwoPhaseNodeField;
    const int ny1 = grid.ny + 1;
    const auto x_p = unmanaged( pv.x_p );
    const auto v_s_p = unmanaged( pv.v_p );
    const auto m_s_p = unmanaged( pv.m_p );
    const auto vol_p = unmanaged( pv.vol_p );
    const auto sigma_p = unmanaged( pv.sigma_p );
    const auto material_p = unmanaged( pv.material_p );
    const auto status_p = unmanaged( pv.status_p );
    const auto p_w_p = unmanaged( wv.p_w_p );
    const auto S_p = unmanaged( wv.S_p );
    const auto n_p = unmanaged( wv.n_p );
    const auto k_rel_p = unmanaged( wv.k_rel_p );
    const auto v_w_p = unmanaged( wv.v_w_p );
    const auto load_p = unmanaged( pv.load_p );
    const auto loads = unmanaged( load_force );

    Kokkos::parallel_for(
        "mpm::p2g_two_phase",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );

            const double vol = vol_p( p );
            const double nS = n_p( p ) * S_p( p );
            const double m_s = m_s_p( p );
            const double m_w = nS * water.density * vol;
            const double p_w = p_w_p( p );
            // Total stress from Bishop, chi = S (Eq. 11), tension positive.
            const double bishop = S_p( p ) * p_w;
            const double s_xx = sigma_p( p, 0 ) - bishop;
            const double s_yy = sigma_p( p, 1 ) - bishop;
            const double s_xy = sigma_p( p, 2 );
            const double permeability_volume =
                materials[material_p( p )].permeability * k_rel_p( p ) * vol;
            double load[2] = { 0.0, 0.0 };
            if ( load_p( p ) >= 0 )
            {
                load[0] = loads( load_p( p ), 0 );
                load[1] = loads( load_p( p ), 1 );
            }
            const double sigma[3] = { sigma_p( p, 0 ), sigma_p( p, 1 ),
                                      sigma_p( p, 2 ) };
            base.addPoint( ci, cj, w, vol, m_s + m_w, sigma, S_p( p ), p_w );
            const double v_s[2] = { v_s_p( p, 0 ), v_s_p( p, 1 ) };
            const double v_w[2] = { v_w_p( p, 0 ), v_w_p( p, 1 ) };
            const double g[2] = { gravity_x, gravity_y };

            const auto node = sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int n = nodeIndex( ci + ( k & 1 ), cj + ( k >> 1 ), ny1 );
                node.touch( n );
                node.add( n, F::m_s, w[k] * m_s );
                node.add( n, F::m_w, w[k] * m_w );
                node.add( n, F::vol, w[k] * vol );
                node.add( n, F::q, w[k] * permeability_volume );
                const double grad[2] = { dwdx[k], dwdy[k] };
                const double div_sigma[2] = { s_xx * dwdx[k] + s_xy * dwdy[k],
                                              s_xy * dwdx[k] + s_yy * dwdy[k] };
                for ( int d = 0; d < 2; ++d )
                {
                    node.add( n, F::mv_s_x + d, w[k] * m_s * v_s[d] );
                    node.add( n, F::mv_w_x + d, w[k] * m_w * v_w[d] );
                    node.add( n, F::f_m_x + d,
                              w[k] * ( ( m_s + m_w ) * g[d] + load[d] ) -
                                  vol * div_sigma[d] );
                    node.add( n, F::f_w_x + d,
                              w[k] * water.density * vol * g[d] +
                                  p_w * vol * grad[d] );
                }
            }
        } );
}

} // namespace mpm

#endif // MPM_P2G_TWO_PHASE_HPP
