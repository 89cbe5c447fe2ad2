#include <mpm_pressure_terms.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_pressure_terms.hpp>

#include <gtest/gtest.h>

#include <vector>

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

// The cells' sums gathered over each cell's points (pressurePointTerms with
// CellPointLists): nodes at rest, so only the storage, the gradient sums
// and the count of free points are nonzero. Four points on a 4 x 4 grid of
// 0.5 m cells: two free ones in cell (1, 1), a prescribed one there too
// (left out of every sum), a free one in cell (2, 2). The sums must equal
// those formed here point by point; after the last point moves to cell
// (0, 2) a second call must zero cell (2, 2) and fill cell (0, 2).
TYPED_TEST( PressurePointTerms,
            cells_gather_their_free_points_and_clear_left_cells )
{
    using exec_space = TypeParam;
    namespace ph = mpm::physics;
    ph::GridGeometry grid;
    grid.h = 0.5;
    grid.nx = grid.ny = 4;
    const int num_points = 4;
    const double n = 0.3, dS_dp = 2.0e-5;
    const double vol[num_points] = { 0.06, 0.07, 0.05, 0.065 };
    const double S[num_points] = { 0.9, 0.6, 0.75, 0.8 };
    const int condition[num_points] = { -1, -1, 0, -1 };
    std::vector<double> x = { 0.6, 0.9, 0.7, 1.2 };
    std::vector<double> y = { 0.55, 0.85, 0.6, 1.1 };
    mpm::ParticleViews<exec_space> points( num_points );
    mpm::WaterParticleViews<exec_space> water_points( num_points );
    mpm::GridViews<exec_space> nodes( grid );
    mpm::WaterGridViews<exec_space> water_nodes( grid );
    Kokkos::deep_copy( points.status_p, mpm::point_active );
    Kokkos::deep_copy( points.m_p, 100.0 );
    Kokkos::deep_copy( water_points.n_p, n );
    Kokkos::deep_copy( water_points.dS_dp_p, dS_dp );
    mpm_test::setPointWater( points, water_points, num_points, vol, S,
                             condition );

    const ph::WaterParams water;
    mpm::PressurePointTerms<exec_space> terms( grid );
    mpm::CellPointLists<exec_space> lists( num_points, grid.nx * grid.ny );
    const auto no_source = KOKKOS_LAMBDA( const int ) { return 0.0; };
    const auto gather = [&]()
    {
        auto x_h = Kokkos::create_mirror_view( points.x_p );
        for ( int p = 0; p < num_points; ++p )
        {
            x_h( p, 0 ) = x[p];
            x_h( p, 1 ) = y[p];
        }
        Kokkos::deep_copy( points.x_p, x_h );
        mpm::pressurePointTerms( exec_space(), points, water_points, nodes,
                                 water_nodes, water, no_source, lists, terms );
    };
    // The sums of cell (ci, cj) formed here from its free points.
    const auto expectCell = [&]( const int ci, const int cj )
    {
        double storage = 0.0, g[8] = {}, g_S[8] = {};
        int count = 0;
        for ( int p = 0; p < num_points; ++p )
        {
            int i, j;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x[p], y[p], i, j, w, dwdx, dwdy );
            if ( i != ci || j != cj || condition[p] >= 0 )
                continue;
            storage +=
                vol[p] * ph::waterStorage( n, S[p], dS_dp, water.bulk_modulus );
            for ( int k = 0; k < 4; ++k )
            {
                g[2 * k] += vol[p] * dwdx[k];
                g[2 * k + 1] += vol[p] * dwdy[k];
                g_S[2 * k] += S[p] * vol[p] * dwdx[k];
                g_S[2 * k + 1] += S[p] * vol[p] * dwdy[k];
            }
            ++count;
        }
        const auto storage_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), terms.storage_c );
        const auto g_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), terms.g_c );
        const auto g_S_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), terms.g_S_c );
        const auto free_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), terms.free_c );
        const auto b_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), terms.b_c );
        EXPECT_EQ( free_h( ci, cj ), count ) << ci << ", " << cj;
        EXPECT_NEAR( storage_h( ci, cj ), storage, 1e-12 * storage + 1e-300 )
            << ci << ", " << cj;
        EXPECT_EQ( b_h( ci, cj ), 0.0 ) << ci << ", " << cj;
        for ( int f = 0; f < 8; ++f )
        {
            EXPECT_NEAR( g_h( ci, cj, f ), g[f], 1e-14 ) << ci << ", " << cj;
            EXPECT_NEAR( g_S_h( ci, cj, f ), g_S[f], 1e-14 )
                << ci << ", " << cj;
        }
    };

    gather();
    EXPECT_EQ( terms.num_touched, 2 );
    expectCell( 1, 1 );
    expectCell( 2, 2 );
    const auto storage_before = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), terms.storage_c );
    EXPECT_GT( storage_before( 2, 2 ), 0.0 );

    x[3] = 0.2;
    y[3] = 1.3;
    gather();
    EXPECT_EQ( terms.num_touched, 2 );
    expectCell( 1, 1 );
    expectCell( 0, 2 );
    expectCell( 2, 2 ); // no points: zeros
    const auto storage_after = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), terms.storage_c );
    EXPECT_EQ( storage_after( 2, 2 ), 0.0 );
    EXPECT_GT( storage_after( 0, 2 ), 0.0 );
}

} // namespace
