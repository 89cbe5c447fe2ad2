#include <mpm_test_backends.hpp>
#include <mpm_velocity_gradient.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_nodal_water.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
MPM_TEST_BACKEND_SUITE( WaterDivergence );

// A point at (xi, eta) = (0.3, 0.6) of cell (0, 0) of 0.5 m cells, the
// solid at rest, its own n S = 0.25 and tr L = 0.1 1/s (L only enters as
// its trace). The water velocity at the nodes is linear in x and y, so the
// bilinear interpolation of the nodal flux q = nS_i (v_w - v_s) has the
// exact divergence 0.3 (b + f) where every node holds nS_i = 0.3.
struct Scene
{
    static constexpr double h = 0.5, xi = 0.3, eta = 0.6;
    static constexpr double nS = 0.3, nS_p = 0.25, trace = 0.1;
    static constexpr double a = 0.2, b = -0.4, c = 0.7; // v_w,x = a + b x + c y
    static constexpr double d = -0.1, e = 0.5, f = 0.9; // v_w,y = d + e x + f y

    static double waterVelocity( const int i, const int j, const int dim )
    {
        const double x = i * h, y = j * h;
        return dim == 0 ? a + b * x + c * y : d + e * x + f * y;
    }
};

//! waterDivergenceAt at the scene's point, node (1, 1) holding nS_dry
//! (and, if that is 0, an infinite water velocity: a node without water
//! must add nothing, not 0 x infinity), the point's n S = nS_p.
template <class ExecSpace>
double divergence( const double nS_dry, const double nS_p )
{
    using S = Scene;
    using memory = typename ExecSpace::memory_space;
    Kokkos::View<double** [2], memory> v_s_i( "v_s_i", 3, 3 );
    Kokkos::View<double** [2], memory> v_w_i( "v_w_i", 3, 3 );
    Kokkos::View<double**, memory> nS_i( "nS_i", 3, 3 );
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 3; ++j )
        {
            nS_i( i, j ) = S::nS;
            for ( int dim = 0; dim < 2; ++dim )
                v_w_i( i, j, dim ) = S::waterVelocity( i, j, dim );
        }
    nS_i( 1, 1 ) = nS_dry;
    if ( !( nS_dry > 0.0 ) )
        v_w_i( 1, 1, 0 ) = v_w_i( 1, 1, 1 ) =
            std::numeric_limits<double>::infinity();

    mpm::physics::GridGeometry grid;
    grid.h = S::h;
    grid.nx = grid.ny = 2;
    int ci, cj;
    double w[4], dwdx[4], dwdy[4];
    grid.weights( S::xi * S::h, S::eta * S::h, ci, cj, w, dwdx, dwdy );
    const double L[2][2] = { { 0.04, 0.3 }, { -0.2, S::trace - 0.04 } };
    return mpm::waterDivergenceAt( ci, cj, dwdx, dwdy, v_s_i, v_w_i, nS_i, nS_p,
                                   L );
}

TYPED_TEST( WaterDivergence, linear_flux_gives_its_exact_divergence )
{
    using S = Scene;
    const double expected = S::nS * ( S::b + S::f ) / S::nS_p + S::trace;
    EXPECT_NEAR( divergence<TypeParam>( S::nS, S::nS_p ), expected,
                 1e-12 * std::fabs( expected ) );
}

TYPED_TEST( WaterDivergence, a_node_without_water_adds_nothing )
{
    using S = Scene;
    // The other three corners' flux: nodes (0, 0), (1, 0), (0, 1) are
    // corners k = 0, 1, 2 with dN/dx = -(1 - eta) / h, (1 - eta) / h,
    // -eta / h and dN/dy = -(1 - xi) / h, -xi / h, (1 - xi) / h.
    const int node[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
    const double dNdx[3] = { -( 1.0 - S::eta ) / S::h, ( 1.0 - S::eta ) / S::h,
                             -S::eta / S::h };
    const double dNdy[3] = { -( 1.0 - S::xi ) / S::h, -S::xi / S::h,
                             ( 1.0 - S::xi ) / S::h };
    double div_q = 0.0;
    for ( int k = 0; k < 3; ++k )
        div_q +=
            S::nS * ( S::waterVelocity( node[k][0], node[k][1], 0 ) * dNdx[k] +
                      S::waterVelocity( node[k][0], node[k][1], 1 ) * dNdy[k] );
    const double expected = div_q / S::nS_p + S::trace;
    EXPECT_NEAR( divergence<TypeParam>( 0.0, S::nS_p ), expected,
                 1e-12 * std::fabs( expected ) );
}

TYPED_TEST( WaterDivergence, a_point_without_water_takes_the_solid_rate )
{
    EXPECT_NEAR( divergence<TypeParam>( Scene::nS, 0.0 ), Scene::trace, 1e-15 );
}

TEST( WaterFraction, is_the_water_volume_per_volume )
{
    // 30 kg of water in 0.1 m^3 of mixture: 0.03 m^3 of water, n S = 0.3.
    EXPECT_DOUBLE_EQ( mpm::physics::waterFraction( 30.0, 0.1, 1000.0 ), 0.3 );
}

} // namespace
