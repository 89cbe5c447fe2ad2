#ifndef MPM_PRESSURE_PICARD_HPP
#define MPM_PRESSURE_PICARD_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_pressure_mobility.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the modified Picard iteration's point sums at a node.
struct PicardNodeField
{
    enum : int
    {
        chord,   //!< lumped chord storage sum N V C_chord / dt, m^3/(Pa s)
        tangent, //!< lumped storage sum N V C(p + dp) / dt, m^3/(Pa s)
        count
    };
};

template <class ExecSpace>
using PicardSums = GridScatter<ExecSpace, PicardNodeField::count>;

//---------------------------------------------------------------------------//
/*!
  \brief The storage of the points at the iterate dp_i (modified Picard,
  Celia et al. 1990; docs/formulation.md §9, item 4), with dp_p = sum_I N_I
  dp_I: the chord C_chord = dtheta / dp_p of the exact change of Eq. 8's
  stored water per unit volume from p_w to p_w + dp_p
  (physics::storedWaterChange, as the explicit step's PorePressureNewton;
  saturated: n S dp_p / K_w; the tangent where dp_p = 0), and the tangent
  C = n dS/dp_w + n S / K_w at p_w + dp_p, both lumped to the nodes as sum
  N V (...) / dt. The chord times the nodal dp holds the points' water
  exactly in the sum over the nodes: sum_I N_I dp_I = dp_p.
*/
template <class ExecSpace, class NodeView>
void picardStorageSums( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const physics::MaterialTable& materials,
                        const physics::WaterParams& water, const bool saturated,
                        const physics::GridGeometry& grid, const NodeView& dp_i,
                        const double dt, const PicardSums<ExecSpace>& sums )
{
    using F = PicardNodeField;
    const auto handle = sums.handle();
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto dp = unmanaged( dp_i );
    const double K_w = water.bulk_modulus;
    forEachPointStencil(
        "mpm::pressure_picard_storage", exec, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            const double dp_p = interpolateAt( stencil, dp );
            const double n = water_points.n_p( p );
            const double S = water_points.S_p( p );
            const double dS_dp = water_points.dS_dp_p( p );
            const double p_w = water_points.p_w_p( p );
            const physics::RetentionParams& retention =
                materials[points.material_p( p )].retention;
            double chord = physics::waterStorage( n, S, dS_dp, K_w );
            double tangent = chord;
            // Saturated at both ends (S = s_sat, dS/dp_w = 0 at p_w and
            // p_w + dp_p >= 0): the storage n S / K_w is linear.
            const bool stays_saturated = p_w >= 0.0 && p_w + dp_p >= 0.0 &&
                                         S == retention.s_sat && dS_dp == 0.0;
            if ( !saturated && dp_p != 0.0 && !stays_saturated )
            {
                const physics::SaturationState state =
                    RetentionAt{ retention }( p_w + dp_p );
                chord = physics::storedWaterChange( n, S, state.S, dp_p, K_w ) /
                        dp_p;
                tangent = physics::waterStorage( n, state.S, state.dS_dp, K_w );
            }
            const double scale = points.vol_p( p ) / dt;
            auto access = handle.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int node =
                    nodeIndex( ci + k % 2, cj + k / 2, grid.ny + 1 );
                access.add( node, F::chord, w[k] * scale * chord );
                access.add( node, F::tangent, w[k] * scale * tangent );
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The modified Picard residual at the unknowns,
    R_I = b_I - (sum_p N_I V_p C_chord,p / dt) dp_I - (L dp)_I,
  L the operator's flow part, (L dp)_I = (A dp)_I - d_I dp_I with `a_dp` =
  A dp and d = storage_i the lumped storage on A's diagonal; then moves
  A's diagonal to the tangent storage at the iterate (picardStorageSums)
  and keeps it in storage_i. Takes the sums of every active node; R = 0
  off the unknowns.
*/
template <class ExecSpace, class NodeView>
void picardResidual(
    const ExecSpace& exec, GridViews<ExecSpace>& gv,
    const Kokkos::View<int**, DeviceType<ExecSpace>>& unknown_i,
    const PicardSums<ExecSpace>& sums, const NodeView& b_i,
    const NodeView& dp_i, const NodeView& a_dp, const NodeView& storage_i,
    const NodeView& residual_i, NodeStencilSystem<ExecSpace>& s )
{
    using F = PicardNodeField;
    const auto handle = sums.handle();
    const auto unknown = unmanaged( unknown_i );
    const auto b = unmanaged( b_i );
    const auto dp = unmanaged( dp_i );
    const auto a_x = unmanaged( a_dp );
    const auto storage = unmanaged( storage_i );
    const auto residual = unmanaged( residual_i );
    const auto a = unmanaged( s.a );
    forEachActiveNode(
        "mpm::pressure_picard_residual", exec, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            const double chord = handle.take( n, F::chord );
            const double store = handle.take( n, F::tangent );
            if ( !unknown( i, j ) )
            {
                residual( i, j ) = 0.0;
                return;
            }
            const double flow = a_x( i, j ) - storage( i, j ) * dp( i, j );
            residual( i, j ) = b( i, j ) - chord * dp( i, j ) - flow;
            a( i, j, 4 ) += store - storage( i, j );
            storage( i, j ) = store;
        } );
}

//! dp_i = base_i + step e_i on the unknowns of s.
template <class ExecSpace, class NodeView>
void stepOverUnknowns( const ExecSpace& exec,
                       const NodeStencilSystem<ExecSpace>& s,
                       const NodeView& base_i, const double step,
                       const NodeView& e_i, const NodeView& dp_i )
{
    const auto nodes = unmanaged( s.nodes );
    const auto base = unmanaged( base_i );
    const auto e = unmanaged( e_i );
    const auto dp = unmanaged( dp_i );
    const int ny1 = static_cast<int>( dp_i.extent( 1 ) );
    Kokkos::parallel_for(
        "mpm::pressure_picard_step",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m ) {
            const int i = nodes( m ) / ny1, j = nodes( m ) % ny1;
            dp( i, j ) = base( i, j ) + step * e( i, j );
        } );
}

} // namespace mpm

#endif // MPM_PRESSURE_PICARD_HPP
