#include <mpm_pressure_terms.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_pressure_terms.hpp>

#include <gtest/gtest.h>

namespace
{
MPM_TEST_BACKEND_SUITE( PressurePointTerms );

// One saturated point of mass m_p in cell (1, 1) of 0.5 m cells, just above
// the cell's lower edge: the cell's two upper nodes carry the point's mass
// times weights of 0.7e-4 and 0.3e-4 (eta (1 - xi), eta xi), below 1 % of it.
// Every node starts at rest (v* = dv); the lower nodes move down by `lower_dv`,
// the upper ones by `upper_dv` (the unbounded f / m of a sliver of mass). The
// right side of the pressure equation in the point's cell, sum V (source -
// r*) with source 0, is V (-r*), and r* = S div v_s* = tr L (saturated,
// v_w = v_s).
template <class exec_space>
double rightSide( const double lower_dv, const double upper_dv )
{
    const double h = 0.5, m_p = 100.0, vol = 0.0625, eta = 1.0e-4, xi = 0.3;
    mpm::physics::GridGeometry grid;
    grid.h = h;
    grid.nx = grid.ny = 4;
    mpm::ParticleViews<exec_space> points( 1 );
    mpm::WaterParticleViews<exec_space> water_points( 1 );
    mpm::GridViews<exec_space> nodes( grid );
    mpm::WaterGridViews<exec_space> water_nodes( grid );
    Kokkos::deep_copy( points.status_p, mpm::point_active );
    Kokkos::deep_copy( points.m_p, m_p );
    Kokkos::deep_copy( points.vol_p, vol );
    Kokkos::deep_copy( water_points.n_p, 0.3 );
    Kokkos::deep_copy( water_points.S_p, 1.0 );
    Kokkos::deep_copy( water_points.k_rel_p, 1.0 );
    Kokkos::deep_copy( water_points.p_w_condition_p, -1 );
    auto x_h = Kokkos::create_mirror_view( points.x_p );
    x_h( 0, 0 ) = ( 1.0 + xi ) * h;
    x_h( 0, 1 ) = ( 1.0 + eta ) * h;
    Kokkos::deep_copy( points.x_p, x_h );

    auto m_h = Kokkos::create_mirror_view( nodes.m_i );
    auto v_h = Kokkos::create_mirror_view( nodes.v_i );
    auto m_w_h = Kokkos::create_mirror_view( water_nodes.m_w_i );
    auto vol_h = Kokkos::create_mirror_view( water_nodes.vol_i );
    auto nS_h = Kokkos::create_mirror_view( water_nodes.nS_i );
    for ( int a = 0; a < 2; ++a )
        for ( int b = 0; b < 2; ++b )
        {
            const double w = ( a ? xi : 1.0 - xi ) * ( b ? eta : 1.0 - eta );
            m_h( 1 + a, 1 + b ) = w * m_p;
            m_w_h( 1 + a, 1 + b ) = w * 0.3 * vol * 1000.0;
            vol_h( 1 + a, 1 + b ) = w * vol;
            nS_h( 1 + a, 1 + b ) = w > 0.0 ? 0.3 : 0.0;
            v_h( 1 + a, 1 + b, 1 ) = b ? upper_dv : lower_dv;
        }
    Kokkos::deep_copy( nodes.m_i, m_h );
    Kokkos::deep_copy( nodes.v_i, v_h );
    Kokkos::deep_copy( nodes.dv_i, v_h );
    Kokkos::deep_copy( water_nodes.m_w_i, m_w_h );
    Kokkos::deep_copy( water_nodes.vol_i, vol_h );
    Kokkos::deep_copy( water_nodes.nS_i, nS_h );
    Kokkos::deep_copy( water_nodes.v_w_i, v_h );
    Kokkos::deep_copy( water_nodes.dv_w_i, v_h );

    const auto terms = mpm_test::pressureTermsWithoutSource(
        grid, points, water_points, nodes, water_nodes );
    auto b_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), terms.b_c );
    return b_h( 1, 1 ) / vol;
}

TYPED_TEST( PressurePointTerms, r_star_takes_the_predictor_of_nodes_with_mass )
{
    // The lower nodes (dN/dy = -(1 - xi) / h and -xi / h) moving down at
    // 1 m/s under nodes at rest: tr L = 1 / h = 2 1/s, the right side -2 V.
    EXPECT_NEAR( rightSide<TypeParam>( -1.0, 0.0 ), -2.0, 1e-9 );
}

TYPED_TEST( PressurePointTerms,
            r_star_ignores_the_acceleration_of_a_mass_sliver )
{
    // The upper nodes hold 0.7e-4 and 0.3e-4 of the point's mass: their dv
    // of 1e3 m/s (what a stress force on that sliver gives) would add
    // 2,000 1/s to r*.
    EXPECT_NEAR( rightSide<TypeParam>( -1.0, 1.0e3 ), -2.0, 1e-9 );
    EXPECT_NEAR( rightSide<TypeParam>( 0.0, 1.0e3 ), 0.0, 1e-9 );
}

} // namespace
