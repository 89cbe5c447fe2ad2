// The semi-implicit step's pressure solve (solveStencilCg, one kernel
// launch per solve) on a square grid of n x n cells: the 9-point stencil of
// bilinear elements with a small storage term on the diagonal (saturated
// soil: 1e-3 of the flow's), every interior node an unknown (n = 34: 1,089
// unknowns, the slope's size), solved from zero to 1e-4 of the right side
// (the slope's linear solves stop between 1e-2 and 5e-5) with each
// preconditioner. Counters: iterations per solve; rate: unknowns solved
// per second.

#include <bench_problem.hpp>

#include <mpm_stencil_cg.hpp>

#include <cmath>
#include <string>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

namespace
{
constexpr double tolerance = 1e-4;

template <class ExecSpace, mpm::CgPreconditioner preconditioner>
void BM_pressureCg( benchmark::State& state )
{
    using node_view = Kokkos::View<double**, mpm::DeviceType<ExecSpace>>;
    const int n = static_cast<int>( state.range( 0 ) );
    mpm::NodeStencilSystem<ExecSpace> system( n, n, ( n - 1 ) * ( n - 1 ) );
    const node_view b( "b", n + 1, n + 1 ), x( "x", n + 1, n + 1 );
    auto a_h = Kokkos::create_mirror_view( system.a );
    auto nodes_h = Kokkos::create_mirror_view( system.nodes );
    auto b_h = Kokkos::create_mirror_view( b );
    int m = 0;
    for ( int i = 1; i < n; ++i )
        for ( int j = 1; j < n; ++j )
        {
            nodes_h( m++ ) = i * ( n + 1 ) + j;
            for ( int k = 0; k < 9; ++k )
                a_h( i, j, k ) = k == 4 ? 8.0 / 3.0 * 1.001 : -1.0 / 3.0;
            b_h( i, j ) = std::sin( 0.3 * i ) * std::cos( 0.2 * j );
        }
    system.num_nodes = m;
    Kokkos::deep_copy( system.a, a_h );
    Kokkos::deep_copy( system.nodes, nodes_h );
    Kokkos::deep_copy( b, b_h );
    mpm::CgWorkspace<ExecSpace> work( n, n );
    const ExecSpace space;

    int iterations = 0;
    for ( auto _ : state )
    {
        Kokkos::deep_copy( space, x, 0.0 );
        const mpm::CgReport report = mpm::solveStencilCg(
            space, system, b, x, work, tolerance, 10 * m, preconditioner );
        space.fence();
        iterations = report.iterations;
        benchmark::DoNotOptimize( report.residual_norm );
    }
    state.counters["unknowns"] = m;
    state.counters["iterations"] = iterations;
    state.SetItemsProcessed( state.iterations() * m );
}

void cgSizes( benchmark::internal::Benchmark* b )
{
    mpm_bench::blockSizes( b, { 21, 34, 100 } );
}

//! Registers the solve on `backend` with each preconditioner.
template <class ExecSpace>
bool addCgBenchmarks( const std::string& backend )
{
    using mpm::CgPreconditioner;
    mpm_bench::addBenchmark(
        "pressure_cg_dilu/" + backend,
        BM_pressureCg<ExecSpace, CgPreconditioner::BlockDilu>, cgSizes );
    mpm_bench::addBenchmark( "pressure_cg_jacobi/" + backend,
                             BM_pressureCg<ExecSpace, CgPreconditioner::Jacobi>,
                             cgSizes );
    return true;
}

const bool serial_cg = addCgBenchmarks<Kokkos::Serial>( "Serial" );
#ifdef KOKKOS_ENABLE_OPENMP
const bool openmp_cg = addCgBenchmarks<Kokkos::OpenMP>( "OpenMP" );
#endif
} // namespace
