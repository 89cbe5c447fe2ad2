#ifndef MPM_CELL_POINT_LISTS_HPP
#define MPM_CELL_POINT_LISTS_HPP

#include <mpm_device_type.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The points of each cell as a compressed list (offset_c, points_c;
  those with a free p_w first), kept current by listCellPoints: the cell
  water equilibrium and the semi-implicit pressure terms gather over them.
  With the cell equilibrium's working storage: each cell's mean p_w and
  point centre (level_c, centre_c), limited pressure slope (slope_c) and
  the range its profile may span (bound_c), and each point's change of
  water volume in the step's equilibrium (change_p).
*/
template <class ExecSpace>
struct CellPointLists
{
    using device_type = DeviceType<ExecSpace>;
    Kokkos::View<int*, device_type> cell_p;   //!< key (listCellPoints), -1 none
    Kokkos::View<int*, device_type> offset_c; //!< nx * ny + 1 offsets
    Kokkos::View<int*, device_type> fill_c;   //!< fill cursor per cell
    Kokkos::View<int*, device_type> points_c; //!< point indices by cell
    Kokkos::View<double*, device_type> level_c;      //!< mean p_w, Pa
    Kokkos::View<double* [2], device_type> centre_c; //!< mean x_p, m
    Kokkos::View<double* [2], device_type> slope_c;  //!< dp_w/dx, Pa/m
    Kokkos::View<double* [2], device_type> bound_c;  //!< p_w range, Pa
    Kokkos::View<double*, device_type> change_p; //!< water volume change, m^3
    Kokkos::View<int*, device_type> occupied;    //!< the cells with points
    int num_occupied = 0;                        //!< in index order

    CellPointLists() = default;
    CellPointLists( const int num_points, const int num_cells )
        : cell_p( "cell_p", num_points )
        , offset_c( "offset_c", num_cells + 1 )
        , fill_c( "fill_c", num_cells )
        , points_c( "points_c", num_points )
        , level_c( "level_c", num_cells )
        , centre_c( "centre_c", num_cells )
        , slope_c( "slope_c", num_cells )
        , bound_c( "bound_c", num_cells )
        , change_p( "water_change_p", num_points )
        , occupied( "occupied_cells", num_cells )
    {
        Kokkos::deep_copy( cell_p, -2 ); // no key: the first call lists
    }
    bool allocated() const { return cell_p.extent( 0 ) > 0; }
};

//---------------------------------------------------------------------------//
/*!
  \brief f(c) for each cell c with points (CellPointLists::occupied), in
  static shares: the cells in index order, column by column, so that a
  thread takes about the cells of its share of the points (which the
  generator orders by cell column) and finds their data in its own cache.
  Each cell's work reads and writes its own cell and points only, and the
  reductions are minima, maxima and integer counts, so the results do not
  depend on how the cells are split. (Over every cell of the grid, most of
  them empty, static halves gave one thread nearly every occupied cell.)
*/
template <class ExecSpace>
Kokkos::RangePolicy<ExecSpace, Kokkos::Schedule<Kokkos::Static>>
occupiedCellPolicy( const ExecSpace& exec_space,
                    const CellPointLists<ExecSpace>& lists )
{
    return Kokkos::RangePolicy<ExecSpace, Kokkos::Schedule<Kokkos::Static>>(
        exec_space, 0, lists.num_occupied );
}

//---------------------------------------------------------------------------//
/*!
  \brief Lists the active points of each cell (count, scan, fill, then
  each cell's list sorted: the points with a free p_w first, each group in
  index order, so that the result does not depend on the threads). Each
  point's key (2 x its cell + 1 if its p_w is prescribed; -1 outside the
  grid or inactive) is kept in cell_p: when no key changed since the last
  call (points rarely leave their cell in a step) the lists are already
  right and are kept.
*/
template <class ExecSpace>
void listCellPoints( const ExecSpace& exec_space,
                     const ParticleViews<ExecSpace>& pv,
                     const WaterParticleViews<ExecSpace>& wv,
                     const physics::GridGeometry& grid,
                     CellPointLists<ExecSpace>& lists )
{
    const int num_cells = grid.nx * grid.ny;
    const int num_points = pv.size();
    const auto points = unmanaged( pv );
    const auto condition_p = unmanaged( wv.p_w_condition_p );
    const auto cell_p = unmanaged( lists.cell_p );
    const auto offset_c = unmanaged( lists.offset_c );
    const auto fill_c = unmanaged( lists.fill_c );
    const auto points_c = unmanaged( lists.points_c );
    const int ny = grid.ny;

    int changed = 0;
    Kokkos::parallel_reduce(
        "mpm::cell_points_keys",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_points ),
        KOKKOS_LAMBDA( const int p, int& count ) {
            int ci, cj, key = -1;
            if ( points.status_p( p ) == point_active &&
                 grid.cellOf( points.x_p( p, 0 ), points.x_p( p, 1 ), ci, cj ) )
                key = 2 * ( ci * ny + cj ) + ( condition_p( p ) >= 0 ? 1 : 0 );
            if ( key != cell_p( p ) )
                ++count;
            cell_p( p ) = key;
        },
        changed );
    if ( changed == 0 )
        return;

    Kokkos::deep_copy( exec_space, lists.fill_c, 0 );
    Kokkos::parallel_for(
        "mpm::cell_points_count",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_points ),
        KOKKOS_LAMBDA( const int p ) {
            if ( cell_p( p ) >= 0 )
                Kokkos::atomic_increment( &fill_c( cell_p( p ) / 2 ) );
        } );
    Kokkos::parallel_scan(
        "mpm::cell_points_offsets",
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
        "mpm::cell_points_fill",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_points ),
        KOKKOS_LAMBDA( const int p ) {
            if ( cell_p( p ) < 0 )
                return;
            const int c = cell_p( p ) / 2;
            points_c( offset_c( c ) +
                      Kokkos::atomic_fetch_add( &fill_c( c ), 1 ) ) = p;
        } );
    const auto occupied = unmanaged( lists.occupied );
    Kokkos::parallel_scan(
        "mpm::cell_points_occupied",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, num_cells ),
        KOKKOS_LAMBDA( const int c, int& k, const bool final ) {
            if ( offset_c( c + 1 ) == offset_c( c ) )
                return;
            if ( final )
                occupied( k ) = c;
            ++k;
        },
        lists.num_occupied );
    Kokkos::parallel_for(
        "mpm::cell_points_sort", occupiedCellPolicy( exec_space, lists ),
        KOKKOS_LAMBDA( const int k ) {
            const int c = occupied( k );
            // Insertion sort (a cell holds a few points).
            const auto key = [&]( const int p )
            { return p + ( cell_p( p ) % 2 == 1 ? num_points : 0 ); };
            const int begin = offset_c( c );
            for ( int a = begin + 1; a < offset_c( c + 1 ); ++a )
            {
                const int q = points_c( a );
                int b = a - 1;
                for ( ; b >= begin && key( points_c( b ) ) > key( q ); --b )
                    points_c( b + 1 ) = points_c( b );
                points_c( b + 1 ) = q;
            }
        } );
}

} // namespace mpm

#endif // MPM_CELL_POINT_LISTS_HPP
