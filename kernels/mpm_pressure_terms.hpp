#ifndef MPM_PRESSURE_TERMS_HPP
#define MPM_PRESSURE_TERMS_HPP

#include <mpm_cell_point_lists.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_node_loop.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_velocity_gradient.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_point_water.hpp>
#include <physics/mpm_water_storage.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the pressure equation's point sums in a cell (its free
//! points'; docs/formulation.md §9, item 3).
struct PressureCellField
{
    enum : int
    {
        rhs,      //!< sum V (source - r*), m^3/s
        storage,  //!< sum V C, m^3/Pa
        grad_0_x, //!< G: sum V dN_k/dx_d, node k = 0..3, m (8 fields)
        grad_S_0_x = grad_0_x + 8, //!< G_S: sum S V dN_k/dx_d, m
        count = grad_S_0_x + 8
    };
};

//! Fields of the pressure equation's point sums at a node (all points).
struct PressureNodeField
{
    enum : int
    {
        volume,     //!< sum N V, m^3
        saturation, //!< sum N V S, m^3
        count
    };
};

/*!
  \brief What the pressure equation needs of the points, per cell: the
  right side b_c, the storage sum storage_c, the gradient sums g_c of
  each of its 4 nodes (G, the nodal water forces of a unit pressure
  increment of the cell's free points per unit water fraction), g_S_c
  (the same weighted by each point's S: the mixture forces, Bishop's
  share) and the number of free points free_c, over the cells with points
  (touched_c, in index order; every other cell holds zeros); per node the
  volume and saturation sums (the nodal S of the mobility).
*/
template <class ExecSpace>
struct PressurePointTerms
{
    using device_type = DeviceType<ExecSpace>;
    using cell_view = Kokkos::View<double**, device_type>;
    GridScatter<ExecSpace, PressureNodeField::count> node_sums;
    Kokkos::View<int*, device_type> touched_c; //!< cells with points
    int num_touched = 0;
    cell_view b_c, storage_c;
    Kokkos::View<double** [8], device_type> g_c;   //!< (k, d) at 2 k + d
    Kokkos::View<double** [8], device_type> g_S_c; //!< as g_c, times S
    Kokkos::View<int**, device_type> free_c;
    //! The fixed-stress split's skeleton storage of each point, 1/Pa
    //! (physics::skeletonStorage), added to its water storage; empty: none.
    Kokkos::View<double*, device_type> skeleton_storage_p;

    PressurePointTerms() = default;
    explicit PressurePointTerms( const physics::GridGeometry& grid )
        : node_sums( "pressure_node_terms", grid.numNodes() )
        , touched_c( "pressure_touched_c", grid.nx * grid.ny )
        , b_c( "pressure_b_c", grid.nx, grid.ny )
        , storage_c( "pressure_storage_c", grid.nx, grid.ny )
        , g_c( "pressure_g_c", grid.nx, grid.ny )
        , g_S_c( "pressure_g_S_c", grid.nx, grid.ny )
        , free_c( "pressure_free_c", grid.nx, grid.ny )
    {
    }
};

//! True if cell (i, j) is an unknown of the pressure equation: it holds a
//! point with a free p_w, and water (storage).
template <class IntView, class CellView>
KOKKOS_INLINE_FUNCTION bool isPressureUnknown( const IntView& free_c,
                                               const CellView& storage_c,
                                               const int i, const int j )
{
    return free_c( i, j ) > 0 && storage_c( i, j ) > 0.0;
}

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
//! The node sums of the pressure equation (PressureNodeField), over every
//! active point: N V and N V S (a scatter; pressureNodeMobility takes them).
template <class ExecSpace>
void pressureNodeTerms( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const physics::GridGeometry& grid,
                        PressurePointTerms<ExecSpace>& t )
{
    using N = PressureNodeField;
    const auto node_sums = t.node_sums.handle();
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    forEachPointStencil(
        "mpm::pressure_node_terms", exec, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const double vol = points.vol_p( p );
            const double S = water_points.S_p( p );
            auto access = node_sums.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int node = nodeIndex( stencil.ci + k % 2,
                                            stencil.cj + k / 2, grid.ny + 1 );
                access.add( node, N::volume, stencil.w[k] * vol );
                access.add( node, N::saturation, stencil.w[k] * vol * S );
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The cell sums of the pressure equation (PressurePointTerms' b_c,
  storage_c, g_c, g_S_c, free_c), gathered cell by cell over the free points
  of `lists` (current: listCellPoints), in index order: no copies to sum,
  the same sums on any number of threads. Per point: the right side
  V (source - r*), r* = div q* + S div v_s* the predictor's water volume
  rate (waterDivergenceAt, waterVolumeRate; PredictorVelocity below 1 % of
  the point's mass), the storage V C (physics::waterStorage, plus the
  skeleton's if t.skeleton_storage_p is set), the
  gradients V grad N of the cell's 4 nodes and the same times S. The cells
  the last call filled that hold no points now are zeroed.
*/
template <class ExecSpace, class Source>
void pressureCellTerms( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const GridViews<ExecSpace>& gv,
                        const WaterGridViews<ExecSpace>& wg,
                        const physics::WaterParams& water, const Source& source,
                        const CellPointLists<ExecSpace>& lists,
                        PressurePointTerms<ExecSpace>& t )
{
    using C = PressureCellField;
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const physics::GridGeometry grid = gv.geometry;
    const auto touched = unmanaged( t.touched_c );
    const auto b = unmanaged( t.b_c );
    const auto storage = unmanaged( t.storage_c );
    const auto g = unmanaged( t.g_c );
    const auto g_S = unmanaged( t.g_S_c );
    const auto free_points = unmanaged( t.free_c );
    const auto skeleton_storage = unmanaged( t.skeleton_storage_p );
    const bool fixed_stress = t.skeleton_storage_p.extent( 0 ) > 0;
    const int ny = grid.ny;
    const auto occupied = unmanaged( lists.occupied );
    const auto offset_c = unmanaged( lists.offset_c );
    const auto points_c = unmanaged( lists.points_c );
    // Below this share of a point's mass a node gives r* its start-of-step
    // velocity (PredictorVelocity).
    const double predictor_mass_share = 0.01;
    const int num_before = t.num_touched, num_now = lists.num_occupied;
    const auto empty = KOKKOS_LAMBDA( const int c )
    {
        return offset_c( c + 1 ) == offset_c( c );
    };
    // Cell (i, j) takes `sums` (PressureCellField) of `count` free points.
    const auto store = KOKKOS_LAMBDA( const int i, const int j,
                                      const double sums[], const int count )
    {
        b( i, j ) = sums[C::rhs];
        storage( i, j ) = sums[C::storage];
        for ( int f = 0; f < 8; ++f )
        {
            g( i, j, f ) = sums[C::grad_0_x + f];
            g_S( i, j, f ) = sums[C::grad_S_0_x + f];
        }
        free_points( i, j ) = count;
    };
    // Index m zeroes the m-th cell of the last call if it is empty now, then
    // fills the m-th cell with points and lists it there (touched_c).
    Kokkos::parallel_for(
        "mpm::pressure_cell_terms",
        Kokkos::RangePolicy<ExecSpace, Kokkos::Schedule<Kokkos::Static>>(
            exec, 0, num_before > num_now ? num_before : num_now ),
        KOKKOS_LAMBDA( const int m ) {
            double sums[C::count] = {};
            if ( m < num_before && empty( touched( m ) ) )
                store( touched( m ) / ny, touched( m ) % ny, sums, 0 );
            if ( m >= num_now )
                return;
            const int c = occupied( m ), ci = c / ny, cj = c % ny;
            touched( m ) = c;
            int count = 0;
            // The points with a free p_w come first.
            for ( int a = offset_c( c ); a < offset_c( c + 1 ); ++a )
            {
                const int p = points_c( a );
                if ( water_points.p_w_condition_p( p ) >= 0 )
                    break;
                int i, j;
                double w[4], dwdx[4], dwdy[4];
                grid.weights( points.x_p( p, 0 ), points.x_p( p, 1 ), i, j, w,
                              dwdx, dwdy );
                const double n = water_points.n_p( p );
                const double S = water_points.S_p( p );
                const double vol = points.vol_p( p );
                const double min_mass = predictor_mass_share * points.m_p( p );
                using Velocity = PredictorVelocity<decltype( nodes.v_i ),
                                                   decltype( nodes.m_i )>;
                const Velocity v_s{ nodes.v_i, nodes.dv_i, nodes.m_i,
                                    min_mass };
                const Velocity v_w{ water_nodes.v_w_i, water_nodes.dv_w_i,
                                    nodes.m_i, min_mass };
                double L[2][2];
                gradientAt( i, j, dwdx, dwdy, v_s, L );
                const double div_v_w = waterDivergenceAt(
                    i, j, dwdx, dwdy, v_s, v_w, water_nodes.nS_i, n * S, L );
                const double rate =
                    physics::waterVolumeRate( n, S, div_v_w, L );
                sums[C::rhs] += vol * ( source( p ) - rate );
                sums[C::storage] +=
                    vol *
                    ( physics::waterStorage( n, S, water_points.dS_dp_p( p ),
                                             water.bulk_modulus ) +
                      ( fixed_stress ? skeleton_storage( p ) : 0.0 ) );
                for ( int k = 0; k < 4; ++k )
                {
                    sums[C::grad_0_x + 2 * k] += vol * dwdx[k];
                    sums[C::grad_0_x + 2 * k + 1] += vol * dwdy[k];
                    sums[C::grad_S_0_x + 2 * k] += S * vol * dwdx[k];
                    sums[C::grad_S_0_x + 2 * k + 1] += S * vol * dwdy[k];
                }
                ++count;
            }
            store( ci, cj, sums, count );
        } );
    t.num_touched = num_now;
}

//---------------------------------------------------------------------------//
/*!
  \brief The points' terms of the semi-implicit pressure equation
  (docs/formulation.md §9, item 3) from the predictor's nodal velocities
  (gv.v_i, wg.v_w_i after gridUpdateTwoPhase): the node sums
  (pressureNodeTerms) and, over `lists` brought up to date
  (listCellPoints), the cell sums (pressureCellTerms). Consumed by
  pressureNodeMobility and assemblePressureOperator. `source(q)` is point
  q's Eq. 8 inflow source, 1/s.
*/
template <class ExecSpace, class Source>
void pressurePointTerms( const ExecSpace& exec,
                         const ParticleViews<ExecSpace>& pv,
                         const WaterParticleViews<ExecSpace>& wv,
                         const GridViews<ExecSpace>& gv,
                         const WaterGridViews<ExecSpace>& wg,
                         const physics::WaterParams& water,
                         const Source& source, CellPointLists<ExecSpace>& lists,
                         PressurePointTerms<ExecSpace>& t )
{
    pressureNodeTerms( exec, pv, wv, gv.geometry, t );
    listCellPoints( exec, pv, wv, gv.geometry, lists );
    pressureCellTerms( exec, pv, wv, gv, wg, water, source, lists, t );
}

} // namespace mpm

#endif // MPM_PRESSURE_TERMS_HPP
