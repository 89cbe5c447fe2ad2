#ifndef MPM_VELOCITY_GRADIENT_HPP
#define MPM_VELOCITY_GRADIENT_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>
#include <mpm_water_views.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
//! L_ab = sum_k v_i(k)_a dN_k/dx_b over the 4 nodes of cell (ci, cj).
template <class VectorView>
KOKKOS_INLINE_FUNCTION void
gradientAt( const int ci, const int cj, const double dwdx[4],
            const double dwdy[4], const VectorView& v_i, double L[2][2] )
{
    L[0][0] = L[0][1] = L[1][0] = L[1][1] = 0.0;
    for ( int k = 0; k < 4; ++k )
    {
        const int i = ci + ( k & 1 );
        const int j = cj + ( k >> 1 );
        for ( int d = 0; d < 2; ++d )
        {
            L[d][0] += v_i( i, j, d ) * dwdx[k];
            L[d][1] += v_i( i, j, d ) * dwdy[k];
        }
    }
}

//---------------------------------------------------------------------------//
/*!
  \brief Velocity gradient at the points from the remapped nodal velocity,
  L_p = sum v_i (x) grad N_i (MUSL).
*/
template <class ExecSpace>
void velocityGradient( const ExecSpace& exec_space,
                       const ParticleViews<ExecSpace>& pv,
                       const GridViews<ExecSpace>& gv )
{
    const auto grid = gv.geometry;
    const auto v_i = gv.v_i;
    const auto x_p = pv.x_p;
    const auto grad_v_p = pv.grad_v_p;
    const auto status_p = pv.status_p;

    Kokkos::parallel_for(
        "mpm::velocity_gradient",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            double L[2][2];
            gradientAt( ci, cj, dwdx, dwdy, v_i, L );
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    grad_v_p( p, a, b ) = L[a][b];
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief B-bar (Hughes 1980): replaces the volumetric part of each point's
  velocity gradient by the volume-weighted average over the points of its
  cell, tr(L_p) <- sum_c vol tr(L) / sum_c vol.
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void cellAverageVolumetricRate( const ExecSpace& exec_space,
                                const ParticleViews<ExecSpace>& pv,
                                GridViews<ExecSpace>& gv )
{
    Kokkos::deep_copy( exec_space, gv.vol_c, 0.0 );
    Kokkos::deep_copy( exec_space, gv.dvol_c, 0.0 );
    auto vol_sv = createScatterSum<ExecSpace, Duplication>( gv.vol_c );
    auto dvol_sv = createScatterSum<ExecSpace, Duplication>( gv.dvol_c );

    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto vol_p = pv.vol_p;
    const auto grad_v_p = pv.grad_v_p;
    const auto status_p = pv.status_p;
    const auto policy =
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() );

    // Sum volume and volume change rate per cell.
    Kokkos::parallel_for(
        "mpm::bbar_cell_sums", policy, KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            if ( status_p( p ) != point_active ||
                 !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
                return;
            auto vol_c = vol_sv.access();
            auto dvol_c = dvol_sv.access();
            vol_c( ci, cj ) += vol_p( p );
            dvol_c( ci, cj ) +=
                vol_p( p ) * ( grad_v_p( p, 0, 0 ) + grad_v_p( p, 1, 1 ) );
        } );
    Kokkos::Experimental::contribute( gv.vol_c, vol_sv );
    Kokkos::Experimental::contribute( gv.dvol_c, dvol_sv );

    // Replace each point's volumetric rate by its cell's average.
    const auto vol_c = gv.vol_c;
    const auto dvol_c = gv.dvol_c;
    Kokkos::parallel_for(
        "mpm::bbar_replace", policy, KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            if ( status_p( p ) != point_active ||
                 !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
                return;
            const double tr_bar = dvol_c( ci, cj ) / vol_c( ci, cj );
            const double correction =
                0.5 * ( tr_bar - grad_v_p( p, 0, 0 ) - grad_v_p( p, 1, 1 ) );
            grad_v_p( p, 0, 0 ) += correction;
            grad_v_p( p, 1, 1 ) += correction;
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Two-phase: the solid velocity gradient (as velocityGradient) and,
  for the water balance (Eq. 8), the equivalent water divergence
  div v_w = div( nS (v_w - v_s) ) / (nS)_p + div v_s, with the relative
  flux nS (v_w - v_s) interpolated from the nodes (nodal nS =
  m_w / (rho_w vol)). Then nS div v_w + (1 - n) S div v_s = div q +
  S div v_s is conservative: the flux leaving one point enters its
  neighbours, also across a wetting front where nS jumps (the point-wise
  nS_p div v_w dropped (v_w - v_s) . grad(nS) and lost about half of the
  infiltrating water there).
*/
template <class ExecSpace>
void velocityGradientTwoPhase( const ExecSpace& exec_space,
                               const ParticleViews<ExecSpace>& pv,
                               const WaterParticleViews<ExecSpace>& wv,
                               const GridViews<ExecSpace>& gv,
                               const WaterGridViews<ExecSpace>& wg,
                               const double water_density )
{
    const auto grid = gv.geometry;
    const auto v_s_i = gv.v_i;
    const auto v_w_i = wg.v_w_i;
    const auto x_p = pv.x_p;
    const auto grad_v_p = pv.grad_v_p;
    const auto div_v_w_p = wv.div_v_w_p;
    const auto status_p = pv.status_p;
    const auto m_w_i = wg.m_w_i;
    const auto vol_i = wg.vol_i;
    const auto n_p = wv.n_p;
    const auto S_p = wv.S_p;

    Kokkos::parallel_for(
        "mpm::velocity_gradient_two_phase",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            double L[2][2];
            gradientAt( ci, cj, dwdx, dwdy, v_s_i, L );
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    grad_v_p( p, a, b ) = L[a][b];
            // Divergence of the relative water flux nS (v_w - v_s).
            double div_q = 0.0;
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                if ( !( m_w_i( i, j ) > 0.0 ) )
                    continue;
                const double nS_i =
                    m_w_i( i, j ) / ( water_density * vol_i( i, j ) );
                div_q += nS_i *
                         ( ( v_w_i( i, j, 0 ) - v_s_i( i, j, 0 ) ) * dwdx[k] +
                           ( v_w_i( i, j, 1 ) - v_s_i( i, j, 1 ) ) * dwdy[k] );
            }
            const double nS_p = n_p( p ) * S_p( p );
            div_v_w_p( p ) =
                ( nS_p > 0.0 ? div_q / nS_p : 0.0 ) + L[0][0] + L[1][1];
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief B-bar for the water: replaces each point's water divergence by the
  volume-weighted average over its cell (call after
  cellAverageVolumetricRate, which leaves the cell volumes in gv.vol_c).
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void cellAverageWaterDivergence( const ExecSpace& exec_space,
                                 const ParticleViews<ExecSpace>& pv,
                                 const WaterParticleViews<ExecSpace>& wv,
                                 const GridViews<ExecSpace>& gv,
                                 WaterGridViews<ExecSpace>& wg )
{
    Kokkos::deep_copy( exec_space, wg.div_w_c, 0.0 );
    auto div_sv = createScatterSum<ExecSpace, Duplication>( wg.div_w_c );
    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto vol_p = pv.vol_p;
    const auto status_p = pv.status_p;
    const auto div_v_w_p = wv.div_v_w_p;
    const auto policy =
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() );

    Kokkos::parallel_for(
        "mpm::bbar_water_sums", policy, KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            if ( status_p( p ) != point_active ||
                 !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
                return;
            auto div_c = div_sv.access();
            div_c( ci, cj ) += vol_p( p ) * div_v_w_p( p );
        } );
    Kokkos::Experimental::contribute( wg.div_w_c, div_sv );

    const auto vol_c = gv.vol_c;
    const auto div_w_c = wg.div_w_c;
    Kokkos::parallel_for(
        "mpm::bbar_water_replace", policy, KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            if ( status_p( p ) != point_active ||
                 !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
                return;
            div_v_w_p( p ) = div_w_c( ci, cj ) / vol_c( ci, cj );
        } );
}

} // namespace mpm

#endif // MPM_VELOCITY_GRADIENT_HPP
