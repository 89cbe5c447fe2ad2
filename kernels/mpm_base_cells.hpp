#ifndef MPM_BASE_CELLS_HPP
#define MPM_BASE_CELLS_HPP

#include <mpm_device_type.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <physics/mpm_base_cell.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_nodal_update.hpp>

#include <Kokkos_Core.hpp>

#include <vector>

namespace mpm
{
//! Fields of the sums of a base cell (physics::BaseCellCompletion).
struct BaseCellField
{
    enum : int
    {
        vol,      //!< sum V_p, m^3
        vol_xi,   //!< sum V_p xi_p (local x in [0, 1])
        vol_eta,  //!< sum V_p eta_p
        sigma_xx, //!< sum V_p sigma'_p (effective, tension positive)
        sigma_yy, //!< ...
        sigma_xy, //!< ...
        bishop,   //!< sum V_p S_p p_w,p
        p_w,      //!< sum V_p p_w,p
        count
    };
};

//! Corner forces of a base cell: mixture x, y and water x, y per corner.
constexpr int base_cell_forces = 16;

//---------------------------------------------------------------------------//
/*!
  \brief The cells cut by a fixed base (a node fixed in x and y and a node
  that is not) and the forces that complete their stress divergence
  (physics::BaseCellCompletion). The step's P2G adds its points' sums
  (addPoint), baseCellForces turns them into corner forces, the grid update
  adds those to the nodes (addNodeForces). Empty when no node is fixed.
*/
template <class ExecSpace>
struct BaseCells
{
    using device_type = DeviceType<ExecSpace>;
    using int_view = Kokkos::View<int**, device_type>;
    using index_view = Kokkos::View<int*, device_type>;
    using force_view = Kokkos::View<double** [base_cell_forces], device_type>;
    using sums_type = GridScatter<ExecSpace, BaseCellField::count>;

    int_view base_c;   //!< 1 for a base cell (nx x ny)
    index_view list_c; //!< flat indices ci * ny + cj of the base cells
    int num_cells = 0;
    force_view force_c; //!< corner forces, N per unit thickness
    sums_type sums;

    BaseCells() = default;

    //! The base cells of the solid's node flags (NodeFlag, nx+1 x ny+1).
    BaseCells( const physics::GridGeometry& grid, const int_view& flags_i )
    {
        auto flags =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), flags_i );
        std::vector<int> cells;
        for ( int i = 0; i < grid.nx; ++i )
            for ( int j = 0; j < grid.ny; ++j )
            {
                int fixed = 0;
                for ( int k = 0; k < 4; ++k )
                    fixed += ( flags( i + ( k & 1 ), j + ( k >> 1 ) ) &
                               node_fixed ) == node_fixed;
                if ( fixed > 0 && fixed < 4 )
                    cells.push_back( i * grid.ny + j );
            }
        num_cells = static_cast<int>( cells.size() );
        if ( num_cells == 0 )
            return;
        base_c = int_view( "base_c", grid.nx, grid.ny );
        list_c = index_view( "base_list_c", num_cells );
        force_c = force_view( "base_force_c", grid.nx, grid.ny );
        sums = sums_type( "base_sums", grid.nx * grid.ny );
        auto base_h = Kokkos::create_mirror_view( base_c );
        auto list_h = Kokkos::create_mirror_view( list_c );
        for ( int c = 0; c < num_cells; ++c )
        {
            list_h( c ) = cells[c];
            base_h( cells[c] / grid.ny, cells[c] % grid.ny ) = 1;
        }
        Kokkos::deep_copy( base_c, base_h );
        Kokkos::deep_copy( list_c, list_h );
    }

    bool active() const { return num_cells > 0; }
};

//---------------------------------------------------------------------------//
/*!
  \brief What kernels capture of BaseCells: the point sums (P2G) and the
  nodes' forces (grid update). `enabled` is false without base cells.
*/
template <class ExecSpace>
struct BaseCellAccess
{
    bool enabled = false;
    int ny = 1;
    UnmanagedView<typename BaseCells<ExecSpace>::int_view> base_c;
    UnmanagedView<typename BaseCells<ExecSpace>::force_view> force_c;
    typename BaseCells<ExecSpace>::sums_type::Handle sums;

    explicit BaseCellAccess( const BaseCells<ExecSpace>& cells,
                             const physics::GridGeometry& grid )
        : enabled( cells.active() )
        , ny( grid.ny )
        , base_c( cells.base_c )
        , force_c( cells.force_c )
        , sums( cells.sums.handle() )
    {
    }

    /*!
      \brief Adds a point of cell (ci, cj) with bilinear weights w, volume
      vol, effective stress sigma (xx, yy, xy), S p_w and p_w to its cell's
      sums if the cell is a base cell.
    */
    KOKKOS_INLINE_FUNCTION void addPoint( const int ci, const int cj,
                                          const double w[4], const double vol,
                                          const double sigma[3],
                                          const double bishop,
                                          const double p_w ) const
    {
        if ( !enabled || !base_c( ci, cj ) )
            return;
        using F = BaseCellField;
        const int c = ci * ny + cj;
        const auto cell = sums.access();
        cell.add( c, F::vol, vol );
        cell.add( c, F::vol_xi, vol * ( w[1] + w[3] ) );
        cell.add( c, F::vol_eta, vol * ( w[2] + w[3] ) );
        cell.add( c, F::sigma_xx, vol * sigma[0] );
        cell.add( c, F::sigma_yy, vol * sigma[1] );
        cell.add( c, F::sigma_xy, vol * sigma[2] );
        cell.add( c, F::bishop, vol * bishop );
        cell.add( c, F::p_w, vol * p_w );
    }

    /*!
      \brief Adds to node (i, j) the forces of its base cells: mixture f_m
      and water f_w (per unit water volume fraction; pass nullptr in a dry
      scene).
    */
    KOKKOS_INLINE_FUNCTION void addNodeForces( const int i, const int j,
                                               const int nx, double f_m[2],
                                               double* f_w ) const
    {
        if ( !enabled )
            return;
        for ( int b = 0; b < 2; ++b )
            for ( int a = 0; a < 2; ++a )
            {
                const int ci = i - 1 + a;
                const int cj = j - 1 + b;
                if ( ci < 0 || cj < 0 || ci >= nx || cj >= ny ||
                     !base_c( ci, cj ) )
                    continue;
                // The node is corner (1 - a) + 2 (1 - b) of that cell.
                const int k = ( 1 - a ) + 2 * ( 1 - b );
                f_m[0] += force_c( ci, cj, 4 * k );
                f_m[1] += force_c( ci, cj, 4 * k + 1 );
                if ( f_w )
                {
                    f_w[0] += force_c( ci, cj, 4 * k + 2 );
                    f_w[1] += force_c( ci, cj, 4 * k + 3 );
                }
            }
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Takes the base cells' sums of the step's P2G and sets their corner
  forces (physics::BaseCellCompletion); a base cell without points gets
  none.
*/
template <class ExecSpace>
void baseCellForces( const ExecSpace& exec_space, BaseCells<ExecSpace>& cells,
                     const physics::GridGeometry& grid )
{
    if ( !cells.active() )
        return;
    const auto sums = cells.sums.handle();
    const auto list_c = unmanaged( cells.list_c );
    const auto force_c = unmanaged( cells.force_c );
    const physics::BaseCellCompletion completion{ grid.h };
    const int ny = grid.ny;

    Kokkos::parallel_for(
        "mpm::base_cell_forces",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, cells.num_cells ),
        KOKKOS_LAMBDA( const int e ) {
            using F = BaseCellField;
            const int c = list_c( e );
            const int ci = c / ny;
            const int cj = c % ny;
            double s[F::count];
            for ( int f = 0; f < F::count; ++f )
                s[f] = sums.take( c, f );
            if ( !( s[F::vol] > 0.0 ) )
            {
                for ( int f = 0; f < base_cell_forces; ++f )
                    force_c( ci, cj, f ) = 0.0;
                return;
            }
            const double inv_vol = 1.0 / s[F::vol];
            const double bishop = s[F::bishop] * inv_vol;
            // Mean total stress, sigma = sigma' - S p_w m (Eq. 11).
            const double sigma[3] = { s[F::sigma_xx] * inv_vol - bishop,
                                      s[F::sigma_yy] * inv_vol - bishop,
                                      s[F::sigma_xy] * inv_vol };
            const double p_w = s[F::p_w] * inv_vol;
            for ( int k = 0; k < 4; ++k )
            {
                double D[2], f_m[2], f_w[2];
                completion.missing( k, s[F::vol], s[F::vol_xi], s[F::vol_eta],
                                    D );
                completion.mixtureForce( D, sigma, f_m );
                completion.waterForce( D, p_w, f_w );
                force_c( ci, cj, 4 * k ) = f_m[0];
                force_c( ci, cj, 4 * k + 1 ) = f_m[1];
                force_c( ci, cj, 4 * k + 2 ) = f_w[0];
                force_c( ci, cj, 4 * k + 3 ) = f_w[1];
            }
        } );
}

} // namespace mpm

#endif // MPM_BASE_CELLS_HPP
