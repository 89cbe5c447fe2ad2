#ifndef MPM_P2G_TWO_PHASE_HPP
#define MPM_P2G_TWO_PHASE_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Two-phase particle-to-grid scatter (formulation.md, step 1):
  solid mass and momentum (gv.m_i, gv.p_i), water mass and momentum,
  mixture force F_m = sum N rho_m V g - sum V sigma . grad N + loads with
  the total (Bishop) stress sigma = sigma' - S p_w m (Eq. 11), and the
  water momentum (Eq. 9) integrated per unit water volume:
  f_w = sum N rho_w V g + sum p_w V grad N (exact integration by parts of
  -grad p_w, no grad(nS) term lost), the permeability sum
  kv = sum N k k_rel V and vol = sum N V; the grid update forms the drag
  from the nodal mean permeability kv / vol and the nodal n S =
  m_w / (rho_w vol).
  `load_force` holds the force (N) on a point of each load condition.
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type,
          class LoadView>
void p2gTwoPhase( const ExecSpace& exec_space,
                  const ParticleViews<ExecSpace>& pv,
                  const WaterParticleViews<ExecSpace>& wv,
                  GridViews<ExecSpace>& gv, WaterGridViews<ExecSpace>& wg,
                  const physics::MaterialTable& materials,
                  const physics::WaterParams& water, const double gravity_x,
                  const double gravity_y, const LoadView& load_force )
{
    // Reset write views.
    Kokkos::deep_copy( exec_space, gv.m_i, 0.0 );
    Kokkos::deep_copy( exec_space, gv.p_i, 0.0 );
    Kokkos::deep_copy( exec_space, gv.f_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.m_w_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.vol_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.mv_w_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.f_w_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.q_i, 0.0 );

    auto m_s_sv = createScatterSum<ExecSpace, Duplication>( gv.m_i );
    auto mv_s_sv = createScatterSum<ExecSpace, Duplication>( gv.p_i );
    auto f_m_sv = createScatterSum<ExecSpace, Duplication>( gv.f_i );
    auto m_w_sv = createScatterSum<ExecSpace, Duplication>( wg.m_w_i );
    auto vol_sv = createScatterSum<ExecSpace, Duplication>( wg.vol_i );
    auto mv_w_sv = createScatterSum<ExecSpace, Duplication>( wg.mv_w_i );
    auto f_w_sv = createScatterSum<ExecSpace, Duplication>( wg.f_w_i );
    auto q_sv = createScatterSum<ExecSpace, Duplication>( wg.q_i );

    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto v_s_p = pv.v_p;
    const auto m_s_p = pv.m_p;
    const auto vol_p = pv.vol_p;
    const auto sigma_p = pv.sigma_p;
    const auto material_p = pv.material_p;
    const auto status_p = pv.status_p;
    const auto p_w_p = wv.p_w_p;
    const auto S_p = wv.S_p;
    const auto n_p = wv.n_p;
    const auto k_rel_p = wv.k_rel_p;
    const auto v_w_p = wv.v_w_p;
    const auto load_p = pv.load_p;

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
                load[0] = load_force( load_p( p ), 0 );
                load[1] = load_force( load_p( p ), 1 );
            }

            auto m_s_i = m_s_sv.access();
            auto mv_s_i = mv_s_sv.access();
            auto f_m_i = f_m_sv.access();
            auto m_w_i = m_w_sv.access();
            auto vol_i = vol_sv.access();
            auto mv_w_i = mv_w_sv.access();
            auto f_w_i = f_w_sv.access();
            auto q_i = q_sv.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                m_s_i( i, j ) += w[k] * m_s;
                m_w_i( i, j ) += w[k] * m_w;
                vol_i( i, j ) += w[k] * vol;
                q_i( i, j ) += w[k] * permeability_volume;
                for ( int d = 0; d < 2; ++d )
                {
                    mv_s_i( i, j, d ) += w[k] * m_s * v_s_p( p, d );
                    mv_w_i( i, j, d ) += w[k] * m_w * v_w_p( p, d );
                }
                const double g[2] = { gravity_x, gravity_y };
                const double grad[2] = { dwdx[k], dwdy[k] };
                const double div_sigma[2] = { s_xx * dwdx[k] + s_xy * dwdy[k],
                                              s_xy * dwdx[k] + s_yy * dwdy[k] };
                for ( int d = 0; d < 2; ++d )
                {
                    f_m_i( i, j, d ) +=
                        w[k] * ( ( m_s + m_w ) * g[d] + load[d] ) -
                        vol * div_sigma[d];
                    f_w_i( i, j, d ) +=
                        w[k] * water.density * vol * g[d] + p_w * vol * grad[d];
                }
            }
        } );

    // Complete the scatter.
    Kokkos::Experimental::contribute( gv.m_i, m_s_sv );
    Kokkos::Experimental::contribute( gv.p_i, mv_s_sv );
    Kokkos::Experimental::contribute( gv.f_i, f_m_sv );
    Kokkos::Experimental::contribute( wg.m_w_i, m_w_sv );
    Kokkos::Experimental::contribute( wg.vol_i, vol_sv );
    Kokkos::Experimental::contribute( wg.mv_w_i, mv_w_sv );
    Kokkos::Experimental::contribute( wg.f_w_i, f_w_sv );
    Kokkos::Experimental::contribute( wg.q_i, q_sv );
}

//---------------------------------------------------------------------------//
/*!
  \brief MUSL remap of both phases' momenta: p_i = sum N m_s v_s,
  mv_w_i = sum N m_w v_w (masses unchanged from the first scatter).
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void p2gMomentumTwoPhase( const ExecSpace& exec_space,
                          const ParticleViews<ExecSpace>& pv,
                          const WaterParticleViews<ExecSpace>& wv,
                          GridViews<ExecSpace>& gv,
                          WaterGridViews<ExecSpace>& wg,
                          const double water_density )
{
    Kokkos::deep_copy( exec_space, gv.p_i, 0.0 );
    Kokkos::deep_copy( exec_space, wg.mv_w_i, 0.0 );
    auto mv_s_sv = createScatterSum<ExecSpace, Duplication>( gv.p_i );
    auto mv_w_sv = createScatterSum<ExecSpace, Duplication>( wg.mv_w_i );

    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto v_s_p = pv.v_p;
    const auto m_s_p = pv.m_p;
    const auto vol_p = pv.vol_p;
    const auto status_p = pv.status_p;
    const auto S_p = wv.S_p;
    const auto n_p = wv.n_p;
    const auto v_w_p = wv.v_w_p;

    Kokkos::parallel_for(
        "mpm::p2g_momentum_two_phase",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            const double m_w = n_p( p ) * S_p( p ) * water_density * vol_p( p );
            auto mv_s_i = mv_s_sv.access();
            auto mv_w_i = mv_w_sv.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                for ( int d = 0; d < 2; ++d )
                {
                    mv_s_i( i, j, d ) += w[k] * m_s_p( p ) * v_s_p( p, d );
                    mv_w_i( i, j, d ) += w[k] * m_w * v_w_p( p, d );
                }
            }
        } );

    Kokkos::Experimental::contribute( gv.p_i, mv_s_sv );
    Kokkos::Experimental::contribute( wg.mv_w_i, mv_w_sv );
}

} // namespace mpm

#endif // MPM_P2G_TWO_PHASE_HPP
