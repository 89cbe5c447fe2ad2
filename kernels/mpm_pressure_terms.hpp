#ifndef MPM_PRESSURE_TERMS_HPP
#define MPM_PRESSURE_TERMS_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_velocity_gradient.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_point_water.hpp>
#include <physics/mpm_pressure_mobility.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the pressure equation's point sums at a node.
struct PressureNodeField
{
    enum : int
    {
        rhs,         //!< sum N V (source - r*), m^3/s
        free_weight, //!< sum N over the points whose p_w is not prescribed
        storage,     //!< lumped storage sum N C V / dt, m^3/(Pa s)
        count
    };
};

//! What the pressure equation needs of the points, per point and per cell.
template <class ExecSpace>
struct PressurePointTerms
{
    using device_type = DeviceType<ExecSpace>;
    Kokkos::View<double*, device_type> mobility_p; //!< M, m^3/kg
    Kokkos::View<double*, device_type> storage_p;  //!< C, 1/Pa
    Kokkos::View<int**, device_type> count_c;      //!< active points per cell
    Kokkos::View<int**, device_type> unknown_i;    //!< 1: a node's dp is solved
    GridScatter<ExecSpace, PressureNodeField::count> sums;

    PressurePointTerms() = default;
    PressurePointTerms( const physics::GridGeometry& grid,
                        const int num_points )
        : mobility_p( "pressure_mobility_p", num_points )
        , storage_p( "pressure_storage_p", num_points )
        , count_c( "pressure_count_c", grid.nx, grid.ny )
        , unknown_i( "pressure_unknown_i", grid.nx + 1, grid.ny + 1 )
        , sums( "pressure_terms", grid.numNodes() )
    {
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief A nodal velocity of the predictor as r* sees it: v* where the node
  carries at least `min_mass` (kg), else its start-of-step velocity v* - dv.
  A node a point barely touches (its mass a sliver of the point's) takes
  the point's stress force on that sliver: its acceleration f / m is
  unbounded as m -> 0. The explicit step never takes a gradient of such a
  node's v*: its velocity gradient comes from the remapped velocities
  (MUSL), which are mass-weighted means of the points' velocities.
*/
template <class VectorView, class ScalarView>
struct PredictorVelocity
{
    VectorView v_i;  //!< v*, m/s
    VectorView dv_i; //!< the step's increment dv, m/s
    ScalarView m_i;  //!< solid mass, kg
    double min_mass; //!< kg

    KOKKOS_INLINE_FUNCTION double operator()( const int i, const int j,
                                              const int d ) const
    {
        return m_i( i, j ) >= min_mass ? v_i( i, j, d )
                                       : v_i( i, j, d ) - dv_i( i, j, d );
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The points' terms of the semi-implicit pressure equation
  (docs/formulation.md §9, item 3), from the predictor's nodal velocities
  (gv.v_i, wg.v_w_i after gridUpdateTwoPhase; PredictorVelocity at a node
  below 1 % of the point's mass): per point its mobility M
  (physics::pressureMobility) and storage C (physics::waterStorage); per
  node the right side sum N V (source - r*), r* = div q* + S div v_s* the
  predictor's water volume rate (waterDivergenceAt, waterVolumeRate), the
  lumped storage sum N C V / dt and the weight of the points whose p_w is
  free; per cell its active points.
  `source(q)` is point q's Eq. 8 inflow source, 1/s.
*/
template <class ExecSpace, class Source>
void pressurePointTerms(
    const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double inertia_scaling, const double dt, const Source& source,
    PressurePointTerms<ExecSpace>& t )
{
    using F = PressureNodeField;
    Kokkos::deep_copy( exec, t.count_c, 0 );
    const auto sums = t.sums.handle();
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto mobility_p = unmanaged( t.mobility_p );
    const auto storage_p = unmanaged( t.storage_p );
    const auto count_c = unmanaged( t.count_c );
    const physics::GridGeometry grid = gv.geometry;
    // Below this share of a point's mass a node gives r* its start-of-step
    // velocity (PredictorVelocity).
    const double predictor_mass_share = 0.01;
    forEachPointStencil(
        "mpm::pressure_point_terms", exec, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            const physics::MaterialParams& params =
                materials[points.material_p( p )];
            const double n = water_points.n_p( p );
            const double S = water_points.S_p( p );
            const double vol = points.vol_p( p );
            const double min_mass = predictor_mass_share * points.m_p( p );
            using Velocity =
                PredictorVelocity<decltype( nodes.v_i ), decltype( nodes.m_i )>;
            const Velocity v_s{ nodes.v_i, nodes.dv_i, nodes.m_i, min_mass };
            const Velocity v_w{ water_nodes.v_w_i, water_nodes.dv_w_i,
                                nodes.m_i, min_mass };
            double L[2][2];
            gradientAt( ci, cj, dwdx, dwdy, v_s, L );
            const double div_v_w = waterDivergenceAt(
                ci, cj, dwdx, dwdy, v_s, v_w, water_nodes.m_w_i,
                water_nodes.vol_i, water.density, n * S, L );
            const double rate = physics::waterVolumeRate( n, S, div_v_w, L );
            mobility_p( p ) =
                physics::pressureMobility(
                    n, S, points.m_p( p ) / vol, water.density,
                    params.permeability, water_points.k_rel_p( p ),
                    water.viscosity, inertia_scaling, dt )
                    .mixture;
            storage_p( p ) = physics::waterStorage(
                n, S, water_points.dS_dp_p( p ), water.bulk_modulus );
            const double store = storage_p( p ) * vol / dt;
            const double inflow = vol * ( source( p ) - rate );
            const bool free = water_points.p_w_condition_p( p ) < 0;
            Kokkos::atomic_add( &count_c( ci, cj ), 1 );
            auto access = sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int node =
                    nodeIndex( ci + k % 2, cj + k / 2, grid.ny + 1 );
                access.add( node, F::rhs, w[k] * inflow );
                access.add( node, F::storage, w[k] * store );
                if ( free )
                    access.add( node, F::free_weight, w[k] );
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Takes the right side into b_i and lists the unknowns of the
  pressure equation into s.nodes (increasing node order): the active nodes
  with solid and water whose support holds a point with a free p_w, none
  of whose cells inside the grid is empty (a free surface, drained: dp = 0
  there, as the explicit step's weak form holds p_w = 0 on it) and which
  do not lie on a drained grid edge (water not tied across it). Every
  other active node is held at dp = 0 (dp_i set to 0 there; the unknowns
  keep theirs, the last step's increment, as the solve's start) and
  storage_i to their lumped storage sum N C V / dt
  (the part of the operator's diagonal the Picard iteration updates).
*/
template <class ExecSpace, class NodeView>
void listPressureUnknowns( const ExecSpace& exec, GridViews<ExecSpace>& gv,
                           const WaterGridViews<ExecSpace>& wg,
                           PressurePointTerms<ExecSpace>& t,
                           const NodeView& b_i, const NodeView& dp_i,
                           const NodeView& storage_i,
                           NodeStencilSystem<ExecSpace>& s )
{
    using F = PressureNodeField;
    const auto sums = t.sums.handle();
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const auto count_c = unmanaged( t.count_c );
    const auto b = unmanaged( b_i );
    const auto dp = unmanaged( dp_i );
    const auto storage = unmanaged( storage_i );
    const auto a = unmanaged( s.a );
    const auto unknown = unmanaged( t.unknown_i );
    const int nx = gv.geometry.nx, ny = gv.geometry.ny;
    forEachActiveNode(
        "mpm::pressure_unknowns", exec, gv,
        KOKKOS_LAMBDA( const int n, const int i, const int j ) {
            b( i, j ) = sums.take( n, F::rhs );
            const double free_weight = sums.take( n, F::free_weight );
            storage( i, j ) = sums.take( n, F::storage );
            bool is_unknown = nodes.m_i( i, j ) > 0.0 &&
                              physics::hasWater( water_nodes.m_w_i( i, j ),
                                                 nodes.m_i( i, j ) ) &&
                              free_weight > 0.0 && a( i, j, 4 ) > 0.0;
            for ( int ci = i - 1; ci <= i; ++ci )
                for ( int cj = j - 1; cj <= j; ++cj )
                    if ( ci >= 0 && ci < nx && cj >= 0 && cj < ny &&
                         count_c( ci, cj ) == 0 )
                        is_unknown = false;
            const int flags_w = water_nodes.flags_w_i( i, j );
            if ( ( i == 0 || i == nx ) && !( flags_w & node_fix_x ) )
                is_unknown = false;
            if ( ( j == 0 || j == ny ) && !( flags_w & node_fix_y ) )
                is_unknown = false;
            b( i, j ) = is_unknown ? b( i, j ) : 0.0;
            dp( i, j ) = is_unknown ? dp( i, j ) : 0.0;
            unknown( i, j ) = is_unknown;
        } );
    const auto active_i = unmanaged( gv.active_i );
    const auto list = unmanaged( s.nodes );
    const int ny1 = ny + 1;
    int count = 0;
    Kokkos::parallel_scan(
        "mpm::pressure_list_unknowns",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, gv.num_active ),
        KOKKOS_LAMBDA( const int m, int& offset, const bool final ) {
            const int n = active_i( m );
            if ( !unknown( n / ny1, n % ny1 ) )
                return;
            if ( final )
                list( offset ) = n;
            ++offset;
        },
        count );
    s.num_nodes = count;
}

} // namespace mpm

#endif // MPM_PRESSURE_TERMS_HPP
