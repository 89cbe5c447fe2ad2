#ifndef MPM_P2G_TWO_PHASE_HPP
#define MPM_P2G_TWO_PHASE_HPP

#include <mpm_base_cells.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_scatter.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_two_phase_scatter.hpp>

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
  \brief Two-phase particle-to-grid scatter (docs/formulation.md, step 1) into
  `sums` (TwoPhaseNodeField), touching the 4 nodes of every active point:
  each point's physics::TwoPhasePoint shared by physics::twoPhaseNodeShare
  (solid and water mass and momentum, the mixture force with the total
  (Bishop) stress of Eq. 11, the water force of Eq. 9 per unit water
  volume, the permeability sum kv = sum N k k_rel V and vol = sum N V); the
  grid update forms the drag from the nodal mean permeability kv / vol and
  the nodal n S = m_w / (rho_w vol) (physics::nodalWater).
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
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto loads = unmanaged( load_force );

    forEachPointStencil(
        "mpm::p2g_two_phase", exec_space, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;

            const double sigma_eff[3] = { points.sigma_p( p, 0 ),
                                          points.sigma_p( p, 1 ),
                                          points.sigma_p( p, 2 ) };
            const int load_index = points.load_p( p );
            double load[2] = { 0.0, 0.0 };
            if ( load_index >= 0 )
            {
                load[0] = loads( load_index, 0 );
                load[1] = loads( load_index, 1 );
            }
            const double v_s[2] = { points.v_p( p, 0 ), points.v_p( p, 1 ) };
            const double v_w[2] = { water_points.v_w_p( p, 0 ),
                                    water_points.v_w_p( p, 1 ) };
            const double g[2] = { gravity_x, gravity_y };
            const double S = water_points.S_p( p );
            const physics::TwoPhasePoint point = physics::twoPhasePoint(
                points.vol_p( p ), water_points.n_p( p ), S,
                water_points.p_w_p( p ), points.m_p( p ), sigma_eff,
                materials[points.material_p( p )].permeability *
                    water_points.k_rel_p( p ),
                v_s, v_w, g, load, water.density );
            base.addPoint( ci, cj, w, point.vol, point.m_s + point.m_w,
                           sigma_eff, S, point.p_w );

            const auto node = sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int n = nodeIndex( ci + ( k & 1 ), cj + ( k >> 1 ), ny1 );
                const double grad_N[2] = { dwdx[k], dwdy[k] };
                const physics::TwoPhaseNodeShare share =
                    physics::twoPhaseNodeShare( point, w[k], grad_N );
                node.touch( n );
                node.add( n, F::m_s, share.m_s );
                node.add( n, F::m_w, share.m_w );
                node.add( n, F::vol, share.vol );
                node.add( n, F::q, share.permeability_volume );
                for ( int d = 0; d < 2; ++d )
                {
                    node.add( n, F::mv_s_x + d, share.mv_s[d] );
                    node.add( n, F::mv_w_x + d, share.mv_w[d] );
                    node.add( n, F::f_m_x + d, share.f_m[d] );
                    node.add( n, F::f_w_x + d, share.f_w[d] );
                }
            }
        } );
}

} // namespace mpm

#endif // MPM_P2G_TWO_PHASE_HPP
