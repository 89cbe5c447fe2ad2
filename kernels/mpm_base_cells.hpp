#ifndef MPM_BASE_CELLS_HPP
#define MPM_BASE_CELLS_HPP

#include <mpm_device_type.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_water_views.hpp>
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
        vol,         //!< sum V_p, m^3
        vol_xi,      //!< sum V_p xi_p (local x in [0, 1])
        vol_eta,     //!< sum V_p eta_p
        vol_xi_eta,  //!< sum V_p xi_p eta_p
        vol_xi_xi,   //!< sum V_p xi_p^2
        vol_eta_eta, //!< sum V_p eta_p^2
        mass,        //!< sum of the points' solid and water masses, kg
        sigma_xx,    //!< sum V_p sigma'_p (effective, tension positive)
        sigma_yy,    //!< ...
        sigma_xy,    //!< ...
        bishop,      //!< sum V_p S_p p_w,p
        p_w,         //!< sum V_p p_w,p
        S,           //!< sum V_p S_p
        count
    };
};

//! Corner forces of a base cell: mixture x, y and water x, y per corner.
constexpr int base_cell_forces = 16;
//! The sums a base cell keeps (after its forces) for baseCellRates.
struct BaseCellKept
{
    enum : int
    {
        vol = base_cell_forces, //!< sum V_p, m^3
        vol_xi,                 //!< sum V_p xi_p
        vol_eta,                //!< sum V_p eta_p
        S,                      //!< mean S
        count
    };
};

//---------------------------------------------------------------------------//
/*!
  \brief The cells a fixed base line cuts (with a node fixed in x and y
  and one that is not) and what completes them (physics::BaseCellCompletion):
  the step's P2G adds its points' sums (addPoint), baseCellForces turns
  them into corner forces (divergence and weight of the empty part), the
  grid update adds those to the nodes (addNodeForces), baseCellRates gives
  the empty part's water balance to the cell's points (extraRate). Empty
  without cut cells.
*/
template <class ExecSpace>
struct BaseCells
{
    using device_type = DeviceType<ExecSpace>;
    using int_view = Kokkos::View<int**, device_type>;
    using index_view = Kokkos::View<int*, device_type>;
    using force_view =
        Kokkos::View<double* * [BaseCellKept::count], device_type>;
    using rate_view = Kokkos::View<double**, device_type>;
    using sums_type = GridScatter<ExecSpace, BaseCellField::count>;

    int_view base_c;   //!< 1 for a base cell (nx x ny)
    index_view list_c; //!< flat indices ci * ny + cj of the base cells
    int num_cells = 0;
    force_view force_c; //!< corner forces, N per unit thickness, and
                        //!< the sums kept (BaseCellKept)
    rate_view rate_c;   //!< water volume rate of the empty part per unit
                        //!< volume of the soil part, 1/s
    sums_type sums;

    BaseCells() = default;

    /*!
      The base cells: those flagged in `cut` (one flag per cell, index
      ci * ny + cj, e.g. cutBaseCells) that have a node fixed in x and y
      (NodeFlag node_fixed in `flags_i`) and one that is not.
    */
    BaseCells( const physics::GridGeometry& grid, const int_view& flags_i,
               const std::vector<int>& cut )
    {
        auto flags =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), flags_i );
        std::vector<int> cells;
        for ( int i = 0; i < grid.nx; ++i )
            for ( int j = 0; j < grid.ny; ++j )
            {
                int fixed = 0;
                for ( int k = 0; k < 4; ++k )
                    fixed +=
                        fullyFixed( flags( i + ( k & 1 ), j + ( k >> 1 ) ) );
                if ( cut[i * grid.ny + j] && fixed > 0 && fixed < 4 )
                    cells.push_back( i * grid.ny + j );
            }
        num_cells = static_cast<int>( cells.size() );
        if ( num_cells == 0 )
            return;
        base_c = int_view( "base_c", grid.nx, grid.ny );
        list_c = index_view( "base_list_c", num_cells );
        force_c = force_view( "base_force_c", grid.nx, grid.ny );
        rate_c = rate_view( "base_rate_c", grid.nx, grid.ny );
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
    UnmanagedView<typename BaseCells<ExecSpace>::rate_view> rate_c;
    typename BaseCells<ExecSpace>::sums_type::Handle sums;

    explicit BaseCellAccess( const BaseCells<ExecSpace>& cells,
                             const physics::GridGeometry& grid )
        : enabled( cells.active() )
        , ny( grid.ny )
        , base_c( cells.base_c )
        , force_c( cells.force_c )
        , rate_c( cells.rate_c )
        , sums( cells.sums.handle() )
    {
    }

    /*!
      \brief Adds a point of cell (ci, cj) with bilinear weights w, volume
      vol, mass (solid and water), effective stress sigma (xx, yy, xy),
      saturation S and p_w to its cell's sums if the cell is a base cell.
    */
    KOKKOS_INLINE_FUNCTION void addPoint( const int ci, const int cj,
                                          const double w[4], const double vol,
                                          const double mass,
                                          const double sigma[3], const double S,
                                          const double p_w ) const
    {
        if ( !enabled || !base_c( ci, cj ) )
            return;
        using F = BaseCellField;
        const int c = ci * ny + cj;
        const auto cell = sums.access();
        const double xi = w[1] + w[3];
        const double eta = w[2] + w[3];
        cell.add( c, F::vol, vol );
        cell.add( c, F::vol_xi, vol * xi );
        cell.add( c, F::vol_eta, vol * eta );
        cell.add( c, F::vol_xi_eta, vol * w[3] );
        cell.add( c, F::vol_xi_xi, vol * xi * xi );
        cell.add( c, F::vol_eta_eta, vol * eta * eta );
        cell.add( c, F::mass, mass );
        cell.add( c, F::sigma_xx, vol * sigma[0] );
        cell.add( c, F::sigma_yy, vol * sigma[1] );
        cell.add( c, F::sigma_xy, vol * sigma[2] );
        cell.add( c, F::bishop, vol * S * p_w );
        cell.add( c, F::p_w, vol * p_w );
        cell.add( c, F::S, vol * S );
    }

    //! Water volume rate a point of cell (ci, cj) takes from the cell's
    //! empty part (baseCellRates), 1/s; 0 outside base cells.
    KOKKOS_INLINE_FUNCTION double extraRate( const int ci, const int cj ) const
    {
        return enabled && base_c( ci, cj ) ? rate_c( ci, cj ) : 0.0;
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
  forces (physics::BaseCellCompletion): the empty part holds its weight
  under gravity (gravity_x, gravity_y), the cell's mean density for the
  mixture, water_density for the water (0 in a dry scene), with the total
  stress and p_w growing with depth from the soil's centre
  (BaseCellCompletion::weightGradients); a base cell without points gets
  none.
*/
template <class ExecSpace>
void baseCellForces( const ExecSpace& exec_space, BaseCells<ExecSpace>& cells,
                     const physics::GridGeometry& grid, const double gravity_x,
                     const double gravity_y, const double water_density )
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
                for ( int f = 0; f < BaseCellKept::count; ++f )
                    force_c( ci, cj, f ) = 0.0;
                return;
            }
            force_c( ci, cj, BaseCellKept::vol ) = s[F::vol];
            force_c( ci, cj, BaseCellKept::vol_xi ) = s[F::vol_xi];
            force_c( ci, cj, BaseCellKept::vol_eta ) = s[F::vol_eta];
            force_c( ci, cj, BaseCellKept::S ) = s[F::S] / s[F::vol];
            const double inv_vol = 1.0 / s[F::vol];
            const double bishop = s[F::bishop] * inv_vol;
            // Mean total stress, sigma = sigma' - S p_w m (Eq. 11).
            const double sigma[3] = { s[F::sigma_xx] * inv_vol - bishop,
                                      s[F::sigma_yy] * inv_vol - bishop,
                                      s[F::sigma_xy] * inv_vol };
            const double p_w = s[F::p_w] * inv_vol;
            const double density = s[F::mass] * inv_vol;
            const double g[2] = { gravity_x, gravity_y };
            const auto gradients =
                completion.weightGradients( g, density, water_density, sigma );
            for ( int k = 0; k < 4; ++k )
            {
                double D[2], E[2][2], f_m[2], f_w[2];
                completion.missing( k, s[F::vol], s[F::vol_xi], s[F::vol_eta],
                                    D );
                completion.missingMoments(
                    k, s[F::vol], s[F::vol_xi], s[F::vol_eta], s[F::vol_xi_eta],
                    s[F::vol_xi_xi], s[F::vol_eta_eta], E );
                completion.mixtureForce( D, E, sigma, gradients.dsigma_dx,
                                         gradients.dsigma_dy, f_m );
                completion.waterForce( D, E, p_w, gradients.dp_w, f_w );
                const double W =
                    completion.missingVolume( k, s[F::vol], s[F::vol_xi],
                                              s[F::vol_eta], s[F::vol_xi_eta] );
                for ( int d = 0; d < 2; ++d )
                {
                    f_m[d] += W * density * g[d];
                    f_w[d] += W * water_density * g[d];
                }
                force_c( ci, cj, 4 * k ) = f_m[0];
                force_c( ci, cj, 4 * k + 1 ) = f_m[1];
                force_c( ci, cj, 4 * k + 2 ) = f_w[0];
                force_c( ci, cj, 4 * k + 3 ) = f_w[1];
            }
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The water balance of a base cell's empty part, from the step's
  remapped nodal velocities: its outflow int (div q + S div v_s) dV =
  sum_k (q_k + S_bar v_s,k) . D_k over the corners (q_k = nS_k (v_w,k -
  v_s,k), nodal nS = m_w / (rho_w vol), WaterGridViews::nS_i; D_k from
  physics::BaseCellCompletion), per unit volume of the cell's soil, into
  rate_c. The soil's points add it to their water volume rate
  (BaseCellAccess::extraRate): the empty part, completed in the momentum
  balance, stores no water and passes what enters it to the soil, so no
  water crosses the base line (without it the nodal relative flux next to
  the base leaked water through it).
*/
template <class ExecSpace>
void baseCellRates( const ExecSpace& exec_space, BaseCells<ExecSpace>& cells,
                    const GridViews<ExecSpace>& gv,
                    const WaterGridViews<ExecSpace>& wg )
{
    if ( !cells.active() )
        return;
    const auto list_c = unmanaged( cells.list_c );
    const auto force_c = unmanaged( cells.force_c );
    const auto rate_c = unmanaged( cells.rate_c );
    const auto nodes = unmanaged( gv );
    const auto water_nodes = unmanaged( wg );
    const physics::BaseCellCompletion completion{ gv.geometry.h };
    const int ny = gv.geometry.ny;

    Kokkos::parallel_for(
        "mpm::base_cell_rates",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, cells.num_cells ),
        KOKKOS_LAMBDA( const int e ) {
            using K = BaseCellKept;
            const int c = list_c( e );
            const int ci = c / ny;
            const int cj = c % ny;
            const double m0 = force_c( ci, cj, K::vol );
            rate_c( ci, cj ) = 0.0;
            if ( !( m0 > 0.0 ) )
                return;
            const double S = force_c( ci, cj, K::S );
            double outflow = 0.0;
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                double D[2];
                completion.missing( k, m0, force_c( ci, cj, K::vol_xi ),
                                    force_c( ci, cj, K::vol_eta ), D );
                const double nS = water_nodes.nS_i( i, j );
                for ( int d = 0; d < 2; ++d )
                    outflow += ( nS * ( water_nodes.v_w_i( i, j, d ) -
                                        nodes.v_i( i, j, d ) ) +
                                 S * nodes.v_i( i, j, d ) ) *
                               D[d];
            }
            rate_c( ci, cj ) = outflow / m0;
        } );
}

} // namespace mpm

#endif // MPM_BASE_CELLS_HPP
