#ifndef MPM_VELOCITY_GRADIENT_HPP
#define MPM_VELOCITY_GRADIENT_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
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
  \brief Water divergence of one point for the water balance (Eq. 8), from
  the divergence of the relative flux nS (v_w - v_s) interpolated from the
  nodes (nodal nS_i = m_w / (rho_w vol), WaterGridViews::nS_i):
  div v_w = div( nS (v_w - v_s) ) / (nS)_p + div v_s. Then
  nS div v_w + (1 - n) S div v_s = div q + S div v_s is conservative: the
  flux leaving one point enters its neighbours, also across a wetting
  front where nS jumps (the point-wise nS_p div v_w dropped
  (v_w - v_s) . grad(nS) and lost about half of the infiltrating water
  there). L is the point's solid velocity gradient, nS_p its n S.
*/
template <class ScalarView, class VectorView>
KOKKOS_INLINE_FUNCTION double
waterDivergenceAt( const int ci, const int cj, const double dwdx[4],
                   const double dwdy[4], const VectorView& v_s_i,
                   const VectorView& v_w_i, const ScalarView& nS_i,
                   const double nS_p, const double L[2][2] )
{
    double div_q = 0.0;
    for ( int k = 0; k < 4; ++k )
    {
        const int i = ci + ( k & 1 );
        const int j = cj + ( k >> 1 );
        const double nS = nS_i( i, j );
        if ( !( nS > 0.0 ) )
            continue;
        div_q += nS * ( ( v_w_i( i, j, 0 ) - v_s_i( i, j, 0 ) ) * dwdx[k] +
                        ( v_w_i( i, j, 1 ) - v_s_i( i, j, 1 ) ) * dwdy[k] );
    }
    return ( nS_p > 0.0 ? div_q / nS_p : 0.0 ) + L[0][0] + L[1][1];
}

//---------------------------------------------------------------------------//
//! Fields of the B-bar cell sums: point volume, volume times tr(L) and
//! (two-phase) volume times div v_w.
struct CellField
{
    enum : int
    {
        vol,
        dvol,
        div_w,
        count
    };
};

//! B-bar sums per cell (flat index ci * ny + cj).
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
using CellSums = GridScatter<ExecSpace, CellField::count, Duplication>;

//---------------------------------------------------------------------------//
/*!
  \brief Velocity gradient of every point, L_p = sum v_i (x) grad N_i
  (gradientAt; two-phase
  also its water divergence, waterDivergenceAt) and, for B-bar (Hughes
  1980), its volume and volume-weighted volumetric rates summed per cell
  into `sums` (CellField). Pass empty water views for a dry scene.
*/
template <class ExecSpace, class Duplication>
void velocityGradientCellSums(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg,
    const GridScatter<ExecSpace, CellField::count, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    const bool two_phase = wv.allocated();
    const auto grid = gv.geometry;
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );

    forEachPointStencil(
        "mpm::velocity_gradient_cell_sums", exec_space, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            double L[2][2];
            gradientAt( ci, cj, dwdx, dwdy, nodes.v_i, L );
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    points.grad_v_p( p, a, b ) = L[a][b];
            double div_v_w = 0.0;
            if ( two_phase )
            {
                div_v_w = waterDivergenceAt(
                    ci, cj, dwdx, dwdy, nodes.v_i, water_nodes.v_w_i,
                    water_nodes.nS_i,
                    water_points.n_p( p ) * water_points.S_p( p ), L );
                water_points.div_v_w_p( p ) = div_v_w;
            }
            // Points on the grid's far edges belong to no cell.
            int cell_i, cell_j;
            if ( !grid.cellOf( points.x_p( p, 0 ), points.x_p( p, 1 ), cell_i,
                               cell_j ) )
                return;
            const int c = cell_i * grid.ny + cell_j;
            const double vol = points.vol_p( p );
            const auto cell = sums.access();
            cell.add( c, CellField::vol, vol );
            cell.add( c, CellField::dvol, vol * ( L[0][0] + L[1][1] ) );
            if ( two_phase )
                cell.add( c, CellField::div_w, vol * div_v_w );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Takes the B-bar cell sums into gv.vol_c, gv.dvol_c (and
  wg.div_w_c if allocated). A cell with points has its lower-left node in
  gv.active_i (the nodes the step's P2G touched), so the loop visits the
  cells of those nodes.
*/
template <class ExecSpace, class Duplication>
void takeCellSums(
    const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
    WaterGridViews<ExecSpace>& wg,
    const GridScatter<ExecSpace, CellField::count, Duplication>& scatter )
{
    const auto sums = scatter.handle();
    const bool two_phase = wg.div_w_c.extent( 0 ) > 0;
    const auto nodes = unmanaged( gv );
    const auto div_w_c = unmanaged( wg.div_w_c );
    const int nx = gv.geometry.nx;
    const int ny = gv.geometry.ny;

    forEachActiveNode(
        "mpm::take_cell_sums", exec_space, gv,
        KOKKOS_LAMBDA( const int, const int i, const int j ) {
            if ( i >= nx || j >= ny )
                return;
            const int c = i * ny + j;
            nodes.vol_c( i, j ) = sums.take( c, CellField::vol );
            nodes.dvol_c( i, j ) = sums.take( c, CellField::dvol );
            if ( two_phase )
                div_w_c( i, j ) = sums.take( c, CellField::div_w );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief B-bar (Hughes 1980) of one point in cell (ci, cj): replaces the
  volumetric part of its velocity gradient by the volume-weighted cell
  average, tr(L) <- sum_c vol tr(L) / sum_c vol.
*/
template <class ScalarView>
KOKKOS_INLINE_FUNCTION void
cellAverageVolumetricRate( const int ci, const int cj, const ScalarView& vol_c,
                           const ScalarView& dvol_c, double L[2][2] )
{
    const double tr_bar = dvol_c( ci, cj ) / vol_c( ci, cj );
    const double correction = 0.5 * ( tr_bar - L[0][0] - L[1][1] );
    L[0][0] += correction;
    L[1][1] += correction;
}

} // namespace mpm

#endif // MPM_VELOCITY_GRADIENT_HPP
