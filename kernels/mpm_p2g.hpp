#ifndef MPM_P2G_HPP
#define MPM_P2G_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Particle-to-grid scatter of mass, momentum and force:
  m_i = sum N m_p, p_i = sum N m_p v_p,
  f_i = sum N (m_p g + load) - sum vol_p sigma_p . grad N.
  `load_force(l, d)` is the force (N) on a point of load l; points with
  load_p < 0 carry none. Resets the grid fields it writes.
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type,
          class LoadView>
void p2gMassMomentumForce( const ExecSpace& exec_space,
                           const ParticleViews<ExecSpace>& pv,
                           GridViews<ExecSpace>& gv, const double gravity_x,
                           const double gravity_y, const LoadView& load_force )
{
    // Reset write views.
    Kokkos::deep_copy( exec_space, gv.m_i, 0.0 );
    Kokkos::deep_copy( exec_space, gv.p_i, 0.0 );
    Kokkos::deep_copy( exec_space, gv.f_i, 0.0 );

    auto m_sv = createScatterSum<ExecSpace, Duplication>( gv.m_i );
    auto p_sv = createScatterSum<ExecSpace, Duplication>( gv.p_i );
    auto f_sv = createScatterSum<ExecSpace, Duplication>( gv.f_i );

    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto v_p = pv.v_p;
    const auto m_p = pv.m_p;
    const auto vol_p = pv.vol_p;
    const auto sigma_p = pv.sigma_p;
    const auto status_p = pv.status_p;
    const auto load_p = pv.load_p;

    Kokkos::parallel_for(
        "mpm::p2g_mass_momentum_force",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );

            auto m_i = m_sv.access();
            auto p_i = p_sv.access();
            auto f_i = f_sv.access();
            const double m = m_p( p );
            const double vol = vol_p( p );
            const double s_xx = sigma_p( p, 0 );
            const double s_yy = sigma_p( p, 1 );
            const double s_xy = sigma_p( p, 2 );
            const int load = load_p( p );
            const double f_x =
                m * gravity_x + ( load >= 0 ? load_force( load, 0 ) : 0.0 );
            const double f_y =
                m * gravity_y + ( load >= 0 ? load_force( load, 1 ) : 0.0 );
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                m_i( i, j ) += w[k] * m;
                p_i( i, j, 0 ) += w[k] * m * v_p( p, 0 );
                p_i( i, j, 1 ) += w[k] * m * v_p( p, 1 );
                f_i( i, j, 0 ) +=
                    w[k] * f_x - vol * ( s_xx * dwdx[k] + s_xy * dwdy[k] );
                f_i( i, j, 1 ) +=
                    w[k] * f_y - vol * ( s_xy * dwdx[k] + s_yy * dwdy[k] );
            }
        } );

    // Complete the scatter.
    Kokkos::Experimental::contribute( gv.m_i, m_sv );
    Kokkos::Experimental::contribute( gv.p_i, p_sv );
    Kokkos::Experimental::contribute( gv.f_i, f_sv );
}

//! p2gMassMomentumForce without loads.
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void p2gMassMomentumForce( const ExecSpace& exec_space,
                           const ParticleViews<ExecSpace>& pv,
                           GridViews<ExecSpace>& gv, const double gravity_x,
                           const double gravity_y )
{
    p2gMassMomentumForce<ExecSpace, Duplication>(
        exec_space, pv, gv, gravity_x, gravity_y,
        LoadForceView<ExecSpace>( "no_loads", 0 ) );
}

//---------------------------------------------------------------------------//
/*!
  \brief MUSL remap: scatter the updated point momenta, p_i = sum N m_p v_p.
  Masses are unchanged from the first scatter of the step.
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void p2gMomentum( const ExecSpace& exec_space,
                  const ParticleViews<ExecSpace>& pv, GridViews<ExecSpace>& gv )
{
    Kokkos::deep_copy( exec_space, gv.p_i, 0.0 );
    auto p_sv = createScatterSum<ExecSpace, Duplication>( gv.p_i );

    const auto grid = gv.geometry;
    const auto x_p = pv.x_p;
    const auto v_p = pv.v_p;
    const auto m_p = pv.m_p;
    const auto status_p = pv.status_p;

    Kokkos::parallel_for(
        "mpm::p2g_momentum",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            auto p_i = p_sv.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + ( k & 1 );
                const int j = cj + ( k >> 1 );
                p_i( i, j, 0 ) += w[k] * m_p( p ) * v_p( p, 0 );
                p_i( i, j, 1 ) += w[k] * m_p( p ) * v_p( p, 1 );
            }
        } );

    Kokkos::Experimental::contribute( gv.p_i, p_sv );
}

} // namespace mpm

#endif // MPM_P2G_HPP
