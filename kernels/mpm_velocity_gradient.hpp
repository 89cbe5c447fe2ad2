#ifndef MPM_VELOCITY_GRADIENT_HPP
#define MPM_VELOCITY_GRADIENT_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
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
            double L[2][2] = { { 0.0, 0.0 }, { 0.0, 0.0 } };
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

} // namespace mpm

#endif // MPM_VELOCITY_GRADIENT_HPP
