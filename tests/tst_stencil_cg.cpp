#include <mpm_stencil_cg.hpp>
#include <mpm_test_backends.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( StencilCg );

const double pi = std::acos( -1.0 );

// -lap p = f for p = sin(pi x) y (1 - y), f = (pi^2 y (1 - y) + 2) sin(pi x),
// on the unit square (p = 0 on its edge; p is not an eigenvector of the
// stencil, so CG needs many iterations),
// with bilinear elements on n x n cells: the 9-point stencil 8/3 at the
// node, -1/3 at each neighbour, and the lumped load h^2 f. Each row may be
// scaled, A' = D A D, b' = D b (d = 1 + 99 x y), whose solution is
// D^-1 x: Jacobi-preconditioned CG takes the same iterations on both.
template <class ExecSpace>
struct PoissonProblem
{
    int n;
    mpm::NodeStencilSystem<ExecSpace> system;
    Kokkos::View<double**, mpm::DeviceType<ExecSpace>> b, x;
    std::vector<double> d; // row scale by flat node index

    PoissonProblem( const int cells, const bool scaled )
        : n( cells )
        , system( cells, cells, ( cells - 1 ) * ( cells - 1 ) )
        , b( "b", cells + 1, cells + 1 )
        , x( "x", cells + 1, cells + 1 )
        , d( ( cells + 1 ) * ( cells + 1 ), 1.0 )
    {
        const double h = 1.0 / n;
        auto a_h = Kokkos::create_mirror_view( system.a );
        auto nodes_h = Kokkos::create_mirror_view( system.nodes );
        auto b_h = Kokkos::create_mirror_view( b );
        Kokkos::deep_copy( a_h, 0.0 );
        Kokkos::deep_copy( b_h, 0.0 );
        for ( int i = 0; i <= n; ++i )
            for ( int j = 0; j <= n; ++j )
                if ( scaled )
                    d[i * ( n + 1 ) + j] = 1.0 + 99.0 * i * h * j * h;
        int m = 0;
        for ( int i = 1; i < n; ++i )
            for ( int j = 1; j < n; ++j )
            {
                nodes_h( m++ ) = i * ( n + 1 ) + j;
                const double di = d[i * ( n + 1 ) + j];
                for ( int k = 0; k < 9; ++k )
                {
                    const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                    a_h( i, j, k ) = di * ( k == 4 ? 8.0 / 3.0 : -1.0 / 3.0 ) *
                                     d[ii * ( n + 1 ) + jj];
                }
                b_h( i, j ) = di * h * h * source( i * h, j * h );
            }
        system.num_nodes = m;
        Kokkos::deep_copy( system.a, a_h );
        Kokkos::deep_copy( system.nodes, nodes_h );
        Kokkos::deep_copy( b, b_h );
    }

    mpm::CgReport solve( const double tolerance )
    {
        mpm::CgWorkspace<ExecSpace> work( n, n );
        return mpm::solveJacobiCg( ExecSpace(), system, b, x, work, tolerance,
                                   10 * n * n );
    }

    static double exact( const double x, const double y )
    {
        return std::sin( pi * x ) * y * ( 1.0 - y );
    }
    static double source( const double x, const double y )
    {
        return ( pi * pi * y * ( 1.0 - y ) + 2.0 ) * std::sin( pi * x );
    }

    // Largest nodal error of D x against the exact p, and the
    // residual |b - A x| / |b| recomputed on the host.
    void errors( double& max_error, double& residual ) const
    {
        const auto a_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), system.a );
        const auto x_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), x );
        const auto b_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), b );
        const double h = 1.0 / n;
        double r2 = 0.0, b2 = 0.0;
        max_error = 0.0;
        for ( int i = 1; i < n; ++i )
            for ( int j = 1; j < n; ++j )
            {
                double ax = 0.0;
                for ( int k = 0; k < 9; ++k )
                    ax += a_h( i, j, k ) * x_h( i + k / 3 - 1, j + k % 3 - 1 );
                r2 += ( b_h( i, j ) - ax ) * ( b_h( i, j ) - ax );
                b2 += b_h( i, j ) * b_h( i, j );
                max_error = std::max(
                    max_error, std::abs( d[i * ( n + 1 ) + j] * x_h( i, j ) -
                                         exact( i * h, j * h ) ) );
            }
        residual = std::sqrt( r2 / b2 );
    }
};

// The discrete solution converges to the analytic one at second order and
// meets the residual asked for.
TYPED_TEST( StencilCg, poisson_converges_at_second_order )
{
    double error[2], residual;
    const int cells[2] = { 16, 32 };
    for ( int c = 0; c < 2; ++c )
    {
        PoissonProblem<TypeParam> problem( cells[c], false );
        const mpm::CgReport report = problem.solve( 1e-10 );
        EXPECT_TRUE( report.converged );
        EXPECT_LE( report.residual_norm, 1e-10 * report.rhs_norm );
        problem.errors( error[c], residual );
        EXPECT_LT( residual, 3e-10 );
        std::printf( "[ cg ] %d cells: %d iterations, max error %.3e\n",
                     cells[c], report.iterations, error[c] );
    }
    EXPECT_LT( error[1], 1.5e-3 ); // 4.95e-4 achieved at 32 cells
    const double order = std::log2( error[0] / error[1] );
    EXPECT_NEAR( order, 2.0, 0.1 );
}

// Jacobi preconditioning makes CG blind to a diagonal scaling of the rows
// and columns (d from 1 to 100): the scaled system takes the same
// iterations and gives the same solution.
TYPED_TEST( StencilCg, jacobi_undoes_a_diagonal_scaling )
{
    PoissonProblem<TypeParam> plain( 32, false ), scaled( 32, true );
    const mpm::CgReport plain_report = plain.solve( 1e-10 );
    const mpm::CgReport scaled_report = scaled.solve( 1e-10 );
    EXPECT_TRUE( scaled_report.converged );
    EXPECT_NEAR( scaled_report.iterations, plain_report.iterations, 2 );
    double error_plain, error_scaled, residual;
    plain.errors( error_plain, residual );
    scaled.errors( error_scaled, residual );
    EXPECT_LT( residual, 3e-10 );
    EXPECT_NEAR( error_scaled, error_plain, 1e-8 );
}

// A start that already solves the system takes no iteration; the nodes off
// the unknowns keep their values.
TYPED_TEST( StencilCg, exact_start_stops_at_once_and_keeps_fixed_nodes )
{
    PoissonProblem<TypeParam> problem( 16, false );
    problem.solve( 1e-12 );
    auto x_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), problem.x );
    x_h( 0, 5 ) = 7.0; // a fixed (edge) node
    Kokkos::deep_copy( problem.x, x_h );
    const mpm::CgReport again = problem.solve( 1e-10 );
    EXPECT_EQ( again.iterations, 0 );
    Kokkos::deep_copy( x_h, problem.x );
    EXPECT_EQ( x_h( 0, 5 ), 7.0 );
}

} // namespace
