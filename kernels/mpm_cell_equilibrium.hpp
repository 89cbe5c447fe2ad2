#ifndef MPM_CELL_EQUILIBRIUM_HPP
#define MPM_CELL_EQUILIBRIUM_HPP

#include <mpm_device_type.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Working storage of the cell equilibrium: the points of each cell
  as a compressed list (offset_c, points_c), rebuilt every step, and each
  point's change of water volume in the step's equilibrium (change_p).
*/
template <class ExecSpace>
struct CellPointLists
{
    using device_type = DeviceType<ExecSpace>;
    Kokkos::View<int*, device_type> cell_p;   //!< cell of each point, -1 none
    Kokkos::View<int*, device_type> offset_c; //!< nx * ny + 1 offsets
    Kokkos::View<int*, device_type> fill_c;   //!< fill cursor per cell
    Kokkos::View<int*, device_type> points_c; //!< point indices by cell
    Kokkos::View<double*, device_type> change_p; //!< water volume change, m^3

    CellPointLists() = default;
    CellPointLists( const int num_points, const int num_cells )
        : cell_p( "cell_p", num_points )
        , offset_c( "offset_c", num_cells + 1 )
        , fill_c( "fill_c", num_cells )
        , points_c( "points_c", num_points )
        , change_p( "water_change_p", num_points )
    {
    }
    bool allocated() const { return cell_p.extent( 0 ) > 0; }
};

//---------------------------------------------------------------------------//
/*!
  \brief physics::CellWaterEquilibrium on every cell (points at their new
  positions, after the step's point update): lists the points of each cell
  (count, scan, fill, then each cell's list in index order so that the
  result does not depend on the threads), solves each cell's common
  pressure and sets it, with the retention state, on the cell's points
  whose p_w is not prescribed (a cell whose points already share one is
  left as it is); the water that moves between them carries its momentum
  (the takers' v_w becomes the mass-weighted mean).
*/
template <class ExecSpace>
void cellWaterEquilibrium(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const physics::GridGeometry& grid,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const bool saturated, const CellPointLists<ExecSpace>& lists )
{
    const int num_cells = grid.nx * grid.ny;
    const auto x_p = unmanaged( pv.x_p );
    const auto vol_p = unmanaged( pv.vol_p );
    const auto status_p = unmanaged( pv.status_p );
    const auto material_p = unmanaged( pv.material_p );
    const auto p_w_p = unmanaged( wv.p_w_p );
    const auto S_p = unmanaged( wv.S_p );
    const auto dS_dp_p = unmanaged( wv.dS_dp_p );
    const auto k_rel_p = unmanaged( wv.k_rel_p );
    const auto n_p = unmanaged( wv.n_p );
    const auto v_w_p = unmanaged( wv.v_w_p );
    const auto condition_p = unmanaged( wv.p_w_condition_p );
    const auto cell_p = unmanaged( lists.cell_p );
    const auto offset_c = unmanaged( lists.offset_c );
    const auto fill_c = unmanaged( lists.fill_c );
    const auto points_c = unmanaged( lists.points_c );
    const auto change_p = unmanaged( lists.change_p );
    const int ny = grid.ny;
    const physics::CellWaterEquilibrium equilibrium{ water.bulk_modulus };

    Kokkos::deep_copy( exec_space, lists.fill_c, 0 );
    Kokkos::parallel_for(
        "mpm::cell_equilibrium_count",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            cell_p( p ) = -1;
            if ( status_p( p ) != point_active || condition_p( p ) >= 0 ||
                 !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
                return;
            cell_p( p ) = ci * ny + cj;
            Kokkos::atomic_increment( &fill_c( ci * ny + cj ) );
        } );
    Kokkos::parallel_scan(
        "mpm::cell_equilibrium_offsets",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_cells ),
        KOKKOS_LAMBDA( const int c, int& offset, const bool final ) {
            const int count = fill_c( c );
            if ( final )
            {
                offset_c( c ) = offset;
                fill_c( c ) = 0;
                if ( c == num_cells - 1 )
                    offset_c( num_cells ) = offset + count;
            }
            offset += count;
        } );
    Kokkos::parallel_for(
        "mpm::cell_equilibrium_fill",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            const int c = cell_p( p );
            if ( c < 0 )
                return;
            points_c( offset_c( c ) +
                      Kokkos::atomic_fetch_add( &fill_c( c ), 1 ) ) = p;
        } );
    Kokkos::parallel_for(
        "mpm::cell_equilibrium_solve",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_cells ),
        KOKKOS_LAMBDA( const int c ) {
            const int begin = offset_c( c );
            const int end = offset_c( c + 1 );
            if ( end - begin < 2 )
                return;
            // Index order (insertion sort; a cell holds a few points).
            for ( int a = begin + 1; a < end; ++a )
            {
                const int q = points_c( a );
                int b = a - 1;
                for ( ; b >= begin && points_c( b ) > q; --b )
                    points_c( b + 1 ) = points_c( b );
                points_c( b + 1 ) = q;
            }
            const auto point = [&]( const int a )
            {
                const int p = points_c( begin + a );
                return physics::CellWaterEquilibrium::Point{
                    vol_p( p ) * n_p( p ), S_p( p ), p_w_p( p ),
                    &materials[material_p( p )].retention };
            };
            bool changed = false;
            const double p_bar =
                equilibrium.solve( end - begin, point, changed );
            if ( !changed )
                return;
            if ( saturated )
            {
                for ( int a = begin; a < end; ++a )
                    p_w_p( points_c( a ) ) = p_bar;
                return;
            }
            // The new state of each point and the water it gives or takes.
            double given = 0.0, given_v[2] = { 0.0, 0.0 };
            for ( int a = begin; a < end; ++a )
            {
                const int p = points_c( a );
                const physics::RetentionState state =
                    RetentionAt{ materials[material_p( p )].retention }.state(
                        p_bar );
                const double change =
                    vol_p( p ) * n_p( p ) * ( state.S - S_p( p ) );
                change_p( p ) = change;
                if ( change < 0.0 )
                {
                    given -= change;
                    given_v[0] -= change * v_w_p( p, 0 );
                    given_v[1] -= change * v_w_p( p, 1 );
                }
                p_w_p( p ) = p_bar;
                S_p( p ) = state.S;
                dS_dp_p( p ) = state.dS_dp;
                k_rel_p( p ) = state.k_rel;
            }
            // The water that moves between the points carries its momentum:
            // the points that give water keep their velocity, those that
            // take it get the mass-weighted mean with the given water's.
            if ( !( given > 0.0 ) )
                return;
            for ( int a = begin; a < end; ++a )
            {
                const int p = points_c( a );
                const double change = change_p( p );
                if ( !( change > 0.0 ) )
                    continue;
                const double after = vol_p( p ) * n_p( p ) * S_p( p );
                for ( int d = 0; d < 2; ++d )
                    v_w_p( p, d ) = ( ( after - change ) * v_w_p( p, d ) +
                                      change * given_v[d] / given ) /
                                    after;
            }
        } );
}

} // namespace mpm

#endif // MPM_CELL_EQUILIBRIUM_HPP
