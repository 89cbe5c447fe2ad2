#include <mpm_stencil_cg.hpp>
#include <mpm_test_backends.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( StencilCg );

const double pi = std::acos( -1.0 );

//! The preconditioners every solve test runs with.
const mpm::CgPreconditioner both_preconditioners[2] = {
    mpm::CgPreconditioner::BlockDilu, mpm::CgPreconditioner::Jacobi };

// -lap p = f for p = sin(pi x) y (1 - y), f = (pi^2 y (1 - y) + 2) sin(pi x),
// on the unit square (p = 0 on its edge; p is not an eigenvector of the
// stencil, so CG needs many iterations),
// with bilinear elements on n x n cells: the 9-point stencil 8/3 at the
// node, -1/3 at each neighbour, and the lumped load h^2 f. Each row may be
// scaled, A' = D A D, b' = D b (d = 1 + 99 x y), whose solution is
// D^-1 x: CG preconditioned by block DILU or Jacobi takes the same
// iterations on both.
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

    mpm::CgReport solve( const double tolerance,
                         const mpm::CgPreconditioner preconditioner =
                             mpm::CgPreconditioner::BlockDilu )
    {
        mpm::CgWorkspace<ExecSpace> work( n, n );
        return mpm::solveStencilCg( ExecSpace(), system, b, x, work, tolerance,
                                    10 * n * n, preconditioner );
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
// meets the residual asked for, with either preconditioner.
TYPED_TEST( StencilCg, poisson_converges_at_second_order )
{
    for ( const auto preconditioner : both_preconditioners )
    {
        double error[2], residual;
        const int cells[2] = { 16, 32 };
        for ( int c = 0; c < 2; ++c )
        {
            PoissonProblem<TypeParam> problem( cells[c], false );
            const mpm::CgReport report = problem.solve( 1e-10, preconditioner );
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
}

// Both preconditioners make CG blind to a diagonal scaling of the rows and
// columns (d from 1 to 100): the scaled system takes the same iterations
// and gives the same solution.
TYPED_TEST( StencilCg, preconditioners_undo_a_diagonal_scaling )
{
    for ( const auto preconditioner : both_preconditioners )
    {
        PoissonProblem<TypeParam> plain( 32, false ), scaled( 32, true );
        const mpm::CgReport plain_report = plain.solve( 1e-10, preconditioner );
        const mpm::CgReport scaled_report =
            scaled.solve( 1e-10, preconditioner );
        EXPECT_TRUE( scaled_report.converged );
        EXPECT_NEAR( scaled_report.iterations, plain_report.iterations, 2 );
        double error_plain, error_scaled, residual;
        plain.errors( error_plain, residual );
        scaled.errors( error_scaled, residual );
        EXPECT_LT( residual, 3e-10 );
        EXPECT_NEAR( error_scaled, error_plain, 1e-8 );
    }
}

// Block DILU takes far fewer iterations than Jacobi on a layered problem
// (the slope's: mobility falling 1,000-fold over the height; 32 cells, an
// irregular load, 1e-10) and reaches the same solution. (On the Poisson
// problem above, whose load excites only the sin(pi x) modes of a
// constant-diagonal stencil, Jacobi is plain CG and needs fewer.)
TYPED_TEST( StencilCg, block_dilu_takes_fewer_iterations_than_jacobi )
{
    const int n = 32;
    mpm::NodeStencilSystem<TypeParam> system( n, n, ( n - 1 ) * ( n - 1 ) );
    auto a_h = Kokkos::create_mirror_view( system.a );
    auto nodes_h = Kokkos::create_mirror_view( system.nodes );
    Kokkos::View<double**, mpm::DeviceType<TypeParam>> b( "b", n + 1, n + 1 );
    auto b_h = Kokkos::create_mirror_view( b );
    Kokkos::deep_copy( a_h, 0.0 );
    Kokkos::deep_copy( b_h, 0.0 );
    // Each link of the 9-point stencil, weight 1/3 at unit mobility, with
    // the mobility 10^(-3 y) at the link's mid-height.
    int m = 0;
    for ( int i = 1; i < n; ++i )
        for ( int j = 1; j < n; ++j )
        {
            nodes_h( m++ ) = i * ( n + 1 ) + j;
            for ( int k = 0; k < 9; ++k )
            {
                if ( k == 4 )
                    continue;
                const double y = ( j + 0.5 * ( k % 3 - 1 ) ) / n;
                const double w = std::pow( 10.0, -3.0 * y ) / 3.0;
                a_h( i, j, 4 ) += w;
                a_h( i, j, k ) = -w;
            }
            b_h( i, j ) = ( std::sin( 0.7 * i + 0.3 * j ) + 0.2 ) / ( n * n );
        }
    system.num_nodes = m;
    Kokkos::deep_copy( system.a, a_h );
    Kokkos::deep_copy( system.nodes, nodes_h );
    Kokkos::deep_copy( b, b_h );

    using node_view = Kokkos::View<double**, mpm::DeviceType<TypeParam>>;
    const node_view x[2] = { node_view( "x_dilu", n + 1, n + 1 ),
                             node_view( "x_jacobi", n + 1, n + 1 ) };
    int iterations[2];
    for ( int c = 0; c < 2; ++c )
    {
        mpm::CgWorkspace<TypeParam> work( n, n );
        const mpm::CgReport report =
            mpm::solveStencilCg( TypeParam(), system, b, x[c], work, 1e-10,
                                 10 * m, both_preconditioners[c] );
        EXPECT_TRUE( report.converged );
        iterations[c] = report.iterations;
    }
    std::printf( "[ cg ] layered, 32 cells: block DILU %d iterations, "
                 "Jacobi %d\n",
                 iterations[0], iterations[1] );
    EXPECT_LT( iterations[0], 0.7 * iterations[1] ); // 48 against 78
    const auto dilu_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), x[0] );
    const auto jacobi_h =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), x[1] );
    double difference = 0.0, largest = 0.0;
    for ( int i = 1; i < n; ++i )
        for ( int j = 1; j < n; ++j )
        {
            difference = std::max(
                difference, std::abs( dilu_h( i, j ) - jacobi_h( i, j ) ) );
            largest = std::max( largest, std::abs( jacobi_h( i, j ) ) );
        }
    EXPECT_LT( difference, 1e-8 * largest );
}

// Unknowns on the grid's edges and around holes (the cells of a slope's
// pressure system): an irregular symmetric positive definite 9-point
// system on a 9 x 7 grid whose edge rows are unknowns, against a dense
// Cholesky solve on the host. A neighbour across the grid's edge must not
// be read (flat index n - 1 at j = 0 is the previous column's top node).
TYPED_TEST( StencilCg, edge_unknowns_match_a_dense_solve )
{
    const int nx1 = 9, ny1 = 7;
    mpm::NodeStencilSystem<TypeParam> system( nx1 - 1, ny1 - 1, nx1 * ny1 );
    Kokkos::View<double**, mpm::DeviceType<TypeParam>> b( "b", nx1, ny1 ),
        x( "x", nx1, ny1 );
    auto a_h = Kokkos::create_mirror_view( system.a );
    auto nodes_h = Kokkos::create_mirror_view( system.nodes );
    auto b_h = Kokkos::create_mirror_view( b );
    Kokkos::deep_copy( a_h, 0.0 );
    const auto isUnknown = [&]( const int i, const int j )
    {
        return i >= 0 && i < nx1 && j >= 0 && j < ny1 &&
               !( i == 4 && j >= 2 && j <= 4 ) && !( i == 7 && j == 0 );
    };
    // A = sum over the unknowns' links of w (e_p - e_q)(e_p - e_q)^T with
    // irregular positive weights, plus a small irregular diagonal.
    std::vector<double> dense( nx1 * ny1 * nx1 * ny1, 0.0 );
    const auto at = [&]( const int p, const int q ) -> double&
    { return dense[p * nx1 * ny1 + q]; };
    for ( int i = 0; i < nx1; ++i )
        for ( int j = 0; j < ny1; ++j )
        {
            if ( !isUnknown( i, j ) )
                continue;
            const int p = i * ny1 + j;
            at( p, p ) += 0.01 * ( 1.0 + ( 3 * i + 5 * j ) % 7 );
            for ( int k = 5; k < 9; ++k ) // links to the upper neighbours
            {
                const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                if ( !isUnknown( ii, jj ) )
                    continue;
                const int q = ii * ny1 + jj;
                const double w = 1.0 + 0.5 * ( ( 7 * i + 3 * j + k ) % 5 );
                at( p, p ) += w;
                at( q, q ) += w;
                at( p, q ) -= w;
                at( q, p ) -= w;
            }
        }
    int m = 0;
    for ( int i = 0; i < nx1; ++i )
        for ( int j = 0; j < ny1; ++j )
        {
            if ( !isUnknown( i, j ) )
                continue;
            nodes_h( m++ ) = i * ny1 + j;
            for ( int k = 0; k < 9; ++k )
            {
                const int ii = i + k / 3 - 1, jj = j + k % 3 - 1;
                if ( isUnknown( ii, jj ) )
                    a_h( i, j, k ) = at( i * ny1 + j, ii * ny1 + jj );
            }
            b_h( i, j ) = std::sin( 0.7 * i + 0.3 * j ) + 0.2;
        }
    system.num_nodes = m;
    Kokkos::deep_copy( system.a, a_h );
    Kokkos::deep_copy( system.nodes, nodes_h );
    Kokkos::deep_copy( b, b_h );

    // The dense solve over the unknowns (Cholesky).
    std::vector<int> flat( m );
    for ( int k = 0; k < m; ++k )
        flat[k] = nodes_h( k );
    std::vector<double> l( m * m, 0.0 ), y( m ), exact( m );
    for ( int r = 0; r < m; ++r )
        for ( int c = 0; c <= r; ++c )
        {
            double sum = at( flat[r], flat[c] );
            for ( int k = 0; k < c; ++k )
                sum -= l[r * m + k] * l[c * m + k];
            l[r * m + c] = r == c ? std::sqrt( sum ) : sum / l[c * m + c];
        }
    for ( int r = 0; r < m; ++r )
    {
        double sum = b_h( flat[r] / ny1, flat[r] % ny1 );
        for ( int k = 0; k < r; ++k )
            sum -= l[r * m + k] * y[k];
        y[r] = sum / l[r * m + r];
    }
    for ( int r = m - 1; r >= 0; --r )
    {
        double sum = y[r];
        for ( int k = r + 1; k < m; ++k )
            sum -= l[k * m + r] * exact[k];
        exact[r] = sum / l[r * m + r];
    }

    for ( const auto preconditioner : both_preconditioners )
    {
        Kokkos::deep_copy( x, 0.0 );
        mpm::CgWorkspace<TypeParam> work( nx1 - 1, ny1 - 1 );
        const mpm::CgReport report = mpm::solveStencilCg(
            TypeParam(), system, b, x, work, 1e-12, 1000, preconditioner );
        EXPECT_TRUE( report.converged );
        const auto x_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), x );
        double worst = 0.0, largest = 0.0;
        for ( int k = 0; k < m; ++k )
        {
            worst =
                std::max( worst, std::abs( x_h( flat[k] / ny1, flat[k] % ny1 ) -
                                           exact[k] ) );
            largest = std::max( largest, std::abs( exact[k] ) );
        }
        EXPECT_LT( worst, 1e-9 * largest )
            << "preconditioner " << static_cast<int>( preconditioner );
    }
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

// A workspace carries each solve's unknowns to the next, which clears only
// those: a solve on fewer unknowns after one on many, from x = 0
// (CgStart::Zero) with anything in x, takes the same iterations and gives
// the same x as a fresh workspace (a stale neighbour's z would change it),
// and leaves x off its unknowns as it was.
TYPED_TEST( StencilCg, reused_workspace_solves_as_a_fresh_one )
{
    const int n = 16;
    PoissonProblem<TypeParam> problem( n, false );
    // The same stencil on the left half's unknowns (i < n / 2): their
    // right neighbours are held at 0.
    mpm::NodeStencilSystem<TypeParam> half = problem.system;
    half.nodes = Kokkos::View<int*, mpm::DeviceType<TypeParam>>(
        "half_nodes", problem.system.num_nodes );
    auto half_h = Kokkos::create_mirror_view( half.nodes );
    int m = 0;
    for ( int i = 1; i < n / 2; ++i )
        for ( int j = 1; j < n; ++j )
            half_h( m++ ) = i * ( n + 1 ) + j;
    half.num_nodes = m;
    Kokkos::deep_copy( half.nodes, half_h );

    using node_view = Kokkos::View<double**, mpm::DeviceType<TypeParam>>;
    const node_view fresh( "fresh", n + 1, n + 1 ),
        reused( "reused", n + 1, n + 1 );
    for ( const auto preconditioner : both_preconditioners )
    {
        mpm::CgWorkspace<TypeParam> fresh_work( n, n ), work( n, n );
        Kokkos::deep_copy( fresh, 0.0 );
        const mpm::CgReport expected =
            mpm::solveStencilCg( TypeParam(), half, problem.b, fresh,
                                 fresh_work, 1e-10, 1000, preconditioner );
        // Every interior node first, then the half from x = 0.
        mpm::solveStencilCg( TypeParam(), problem.system, problem.b, problem.x,
                             work, 1e-10, 1000, preconditioner );
        Kokkos::deep_copy( reused, 5.0 );
        const mpm::CgReport report = mpm::solveStencilCg(
            TypeParam(), half, problem.b, reused, work, 1e-10, 1000,
            preconditioner, mpm::CgStart::Zero );
        EXPECT_TRUE( report.converged );
        EXPECT_EQ( report.iterations, expected.iterations );
        const auto fresh_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), fresh );
        const auto reused_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), reused );
        double worst = 0.0, largest = 0.0;
        for ( int i = 0; i <= n; ++i )
            for ( int j = 0; j <= n; ++j )
                if ( i >= 1 && i < n / 2 && j >= 1 && j < n )
                {
                    worst = std::max(
                        worst, std::abs( reused_h( i, j ) - fresh_h( i, j ) ) );
                    largest = std::max( largest, std::abs( fresh_h( i, j ) ) );
                }
                else
                    EXPECT_EQ( reused_h( i, j ), 5.0 );
        EXPECT_LT( worst, 1e-12 * largest )
            << "preconditioner " << static_cast<int>( preconditioner );
    }
}

} // namespace
