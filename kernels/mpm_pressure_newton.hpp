#ifndef MPM_PRESSURE_NEWTON_HPP
#define MPM_PRESSURE_NEWTON_HPP

#include <mpm_grid_scatter.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_retention.hpp>
#include <physics/mpm_water_storage.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fields of the Newton iteration's point sums in a cell.
struct NewtonCellField
{
    enum : int
    {
        stored,  //!< water the free points store, sum V dtheta / dt, m^3/s
        tangent, //!< their storage at the iterate, sum V C / dt, m^3/(Pa s)
        count
    };
};

template <class ExecSpace>
using NewtonSums = GridScatter<ExecSpace, NewtonCellField::count>;

//! f(c, i, j) for each unknown cell of s: its flat index c = i ny + j.
template <class ExecSpace, class Functor>
void forEachUnknownCell( const char* label, const ExecSpace& exec,
                         const NodeStencilSystem<ExecSpace>& s, const int ny,
                         const Functor& f )
{
    const auto cells = unmanaged( s.nodes );
    Kokkos::parallel_for(
        label, Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m ) {
            const int c = cells( m );
            f( c, c / ny, c % ny );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The Newton iteration's start on a step's unknowns: dp_c = 0 off
  them (on them it keeps the last step's increment) and, on them, K's
  diagonal (A's, as assembled) into k_diagonal_c.
*/
template <class ExecSpace, class CellView>
void keepPressureStartOnUnknowns( const ExecSpace& exec,
                                  const physics::GridGeometry& grid,
                                  const PressurePointTerms<ExecSpace>& terms,
                                  const NodeStencilSystem<ExecSpace>& system,
                                  const CellView& dp_c,
                                  const CellView& k_diagonal_c )
{
    const auto free_points = unmanaged( terms.free_c );
    const auto storage = unmanaged( terms.storage_c );
    const auto dp = unmanaged( dp_c );
    const auto k_diagonal = unmanaged( k_diagonal_c );
    const auto a = unmanaged( system.a );
    const int ny = grid.ny;
    Kokkos::parallel_for(
        "mpm::pressure_start",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, grid.nx * grid.ny ),
        KOKKOS_LAMBDA( const int c ) {
            const int i = c / ny, j = c % ny;
            if ( isPressureUnknown( free_points, storage, i, j ) )
                k_diagonal( i, j ) = a( i, j, 4 );
            else
                dp( i, j ) = 0.0;
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The storage of each cell's free points at its iterate dp_c
  (docs/formulation.md §9, item 4): the exact change of Eq. 8's stored
  water from p_w to p_w + dp_c, dtheta = n (S(p_w + dp_c) - S(p_w)) +
  n S dp_c / K_w (physics::storedWaterChange, as the explicit step's
  PorePressureNewton; saturated: n S dp_c / K_w), and the tangent C =
  n dS/dp_w + n S / K_w at p_w + dp_c, summed as V (...) / dt. Each
  point takes only its own cell's dp_c, so the tangent is the exact
  derivative of the stored water (Newton's). With t.skeleton_storage_p
  set, each point's skeleton storage adds its linear share (the
  fixed-stress split, docs/formulation.md §11). Only the unknown cells'
  points add (isPressureUnknown).
*/
template <class ExecSpace, class CellView>
void newtonStorageSums( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const physics::MaterialTable& materials,
                        const physics::WaterParams& water, const bool saturated,
                        const physics::GridGeometry& grid,
                        const PressurePointTerms<ExecSpace>& t,
                        const CellView& dp_c, const double dt,
                        const NewtonSums<ExecSpace>& sums )
{
    using F = NewtonCellField;
    const auto handle = sums.handle();
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto dp = unmanaged( dp_c );
    const auto free_points = unmanaged( t.free_c );
    const auto storage = unmanaged( t.storage_c );
    const auto skeleton_storage = unmanaged( t.skeleton_storage_p );
    const bool fixed_stress = t.skeleton_storage_p.extent( 0 ) > 0;
    const double K_w = water.bulk_modulus;
    Kokkos::parallel_for(
        "mpm::pressure_newton_storage",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            int ci, cj;
            if ( points.status_p( p ) != point_active ||
                 water_points.p_w_condition_p( p ) >= 0 ||
                 !grid.cellOf( points.x_p( p, 0 ), points.x_p( p, 1 ), ci,
                               cj ) ||
                 !isPressureUnknown( free_points, storage, ci, cj ) )
                return;
            const double dp_p = dp( ci, cj );
            const double n = water_points.n_p( p );
            const double S = water_points.S_p( p );
            const double dS_dp = water_points.dS_dp_p( p );
            const double p_w = water_points.p_w_p( p );
            const physics::RetentionParams& retention =
                materials[points.material_p( p )].retention;
            double tangent = physics::waterStorage( n, S, dS_dp, K_w );
            double stored = tangent * dp_p;
            // Saturated at both ends (S = s_sat, dS/dp_w = 0 at p_w and
            // p_w + dp_p >= 0): the storage n S / K_w is linear.
            const bool stays_saturated = p_w >= 0.0 && p_w + dp_p >= 0.0 &&
                                         S == retention.s_sat && dS_dp == 0.0;
            if ( !saturated && dp_p != 0.0 && !stays_saturated )
            {
                const physics::SaturationState state =
                    RetentionAt{ retention }( p_w + dp_p );
                stored = physics::storedWaterChange( n, S, state.S, dp_p, K_w );
                tangent = physics::waterStorage( n, state.S, state.dS_dp, K_w );
            }
            if ( fixed_stress )
            {
                stored += skeleton_storage( p ) * dp_p;
                tangent += skeleton_storage( p );
            }
            const double scale = points.vol_p( p ) / dt;
            auto access = handle.access();
            const int cell = ci * grid.ny + cj;
            access.add( cell, F::stored, scale * stored );
            access.add( cell, F::tangent, scale * tangent );
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief The water residual at the unknown cells of s, in one pass,
    R_c = b_c - sum_p V dtheta_p / dt - (K dp)_c,
  with K dp the flow part of A (its neighbours' entries and K's own
  diagonal `k_diagonal`, whatever A's diagonal holds); then puts K's
  diagonal plus the tangent storage at the iterate on A's diagonal (a row
  writes only its own diagonal, which no other row reads). Takes the sums
  of the unknowns (newtonStorageSums: only the unknowns' points contribute,
  every other cell's dp is 0). Returns |R|^2 over the unknowns.
*/
template <class ExecSpace, class CellView>
double newtonResidual( const ExecSpace& exec, const NewtonSums<ExecSpace>& sums,
                       const CellView& b_c, const CellView& k_diagonal_c,
                       const CellView& dp_c, const CellView& residual_c,
                       NodeStencilSystem<ExecSpace>& s )
{
    using F = NewtonCellField;
    static_assert( std::is_same<typename CellView::array_layout,
                                Kokkos::LayoutRight>::value,
                   "newtonResidual: cell views must be LayoutRight" );
    const auto handle = sums.handle();
    const double* const b = b_c.data();
    const double* const k_diagonal = k_diagonal_c.data();
    const double* const dp = dp_c.data();
    double* const residual = residual_c.data();
    double* const a = s.a.data();
    const int nx = static_cast<int>( s.a.extent( 0 ) );
    const int ny = static_cast<int>( s.a.extent( 1 ) );
    return Impl::sumOverUnknowns(
        "mpm::pressure_newton_residual", exec, s, KOKKOS_LAMBDA( const int c ) {
            const double k_dp =
                Impl::neighbourSum( a, dp, c, nx, ny ) + k_diagonal[c] * dp[c];
            const double r = b[c] - handle.take( c, F::stored ) - k_dp;
            residual[c] = r;
            a[9 * c + 4] = k_diagonal[c] + handle.take( c, F::tangent );
            return r * r;
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief newtonResidual at dp = 0 without a pass over the points: there
  the stored water is 0 and the tangent storage is the points' storage at
  their p_w, storage_c / dt (pressurePointTerms, with the stored retention
  state), so R_c = b_c and A's diagonal is K's plus storage_c / dt. Sets
  dp = 0 on the unknowns; returns |R|^2 = |b|^2.
*/
template <class ExecSpace, class CellView>
double newtonResidualAtZero( const ExecSpace& exec, const CellView& b_c,
                             const CellView& storage_c,
                             const CellView& k_diagonal_c, const double dt,
                             const CellView& dp_c, const CellView& residual_c,
                             NodeStencilSystem<ExecSpace>& s )
{
    const double* const b = b_c.data();
    const double* const storage = storage_c.data();
    const double* const k_diagonal = k_diagonal_c.data();
    double* const dp = dp_c.data();
    double* const residual = residual_c.data();
    double* const a = s.a.data();
    return Impl::sumOverUnknowns(
        "mpm::pressure_newton_residual_at_zero", exec, s,
        KOKKOS_LAMBDA( const int c ) {
            dp[c] = 0.0;
            residual[c] = b[c];
            a[9 * c + 4] = k_diagonal[c] + storage[c] / dt;
            return b[c] * b[c];
        } );
}

//! dp += step e on the unknowns of s.
template <class ExecSpace, class CellView>
void stepOverUnknowns( const ExecSpace& exec,
                       const NodeStencilSystem<ExecSpace>& s, const double step,
                       const CellView& e_c, const CellView& dp_c )
{
    const auto e = unmanaged( e_c );
    const auto dp = unmanaged( dp_c );
    forEachUnknownCell(
        "mpm::pressure_newton_step", exec, s,
        static_cast<int>( dp_c.extent( 1 ) ),
        KOKKOS_LAMBDA( const int, const int i, const int j ) {
            dp( i, j ) += step * e( i, j );
        } );
}

} // namespace mpm

#endif // MPM_PRESSURE_NEWTON_HPP
