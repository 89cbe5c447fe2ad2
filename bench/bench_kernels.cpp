// Kernel and step benchmarks of the dry MUSL step on the soil block
// (bench_problem.hpp): the kernels Simulation::advanceDry runs. Names:
// <kernel>/<backend>/<scatter>/cells_high:<n>, scatter = plain (Serial),
// duplicated, atomic (OpenMP non-duplicated) or none (no scatter). Rates
// are material-point updates/s.

#include <bench_problem.hpp>

#include <mpm_scatter.hpp>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

namespace
{
namespace KE = Kokkos::Experimental;
using mpm_bench::BlockProblem;
using mpm_bench::PointState;

//---------------------------------------------------------------------------//
//! Times phases(problem, step) (fenced) on the block of the benchmark's
//! size, `step` a DryStepPhases with the benchmark's scatter strategy,
//! after an untimed prepare(problem); with `grid_updated` (a grid update
//! ran) it also reports the nodes the grid phases loop over.
template <class ExecSpace, class Duplication, class Prepare, class Phases>
void timeDryPhases( benchmark::State& state, const Prepare& prepare,
                    const Phases& phases, const bool grid_updated )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    const mpm::DryStepPhases<ExecSpace, Duplication> step(
        problem.sim.grid.geometry );
    prepare( problem );
    problem.space.fence();
    for ( auto _ : state )
    {
        phases( problem, step );
        problem.space.fence();
    }
    problem.setCounters( state );
    if ( grid_updated )
        state.counters["active_nodes"] = problem.sim.grid.num_active;
}

//! P2G scatter of mass, momentum and force into sums kept between steps.
//! Nothing takes them here: they grow, the work per iteration does not.
template <class ExecSpace, class Duplication>
void BM_p2g( benchmark::State& state )
{
    timeDryPhases<ExecSpace, Duplication>(
        state, []( auto& ) {},
        []( auto& problem, const auto& step ) { problem.scatter( step ); },
        false );
}

//! P2G and the grid update that takes its sums (the pair as the step runs
//! it: the grid update's own cost is the difference to p2g).
template <class ExecSpace, class Duplication>
void BM_p2gGridUpdate( benchmark::State& state )
{
    timeDryPhases<ExecSpace, Duplication>(
        state, []( auto& ) {},
        []( auto& problem, const auto& step )
        {
            problem.scatter( step );
            problem.gridUpdate( step );
        },
        true );
}

//! G2P with the MUSL remap scatter, and the remap, on the grid of one
//! (untimed) P2G and grid update. Repeating them from the same grid is a
//! contraction of v_p (FLIP fraction < 1) and a projection of v_i: the
//! state stays bounded, no restore.
template <class ExecSpace, class Duplication>
void BM_g2pRemap( benchmark::State& state )
{
    timeDryPhases<ExecSpace, Duplication>(
        state,
        []( auto& problem )
        {
            problem.scatter( problem.phases );
            problem.gridUpdate( problem.phases );
        },
        []( auto& problem, const auto& step )
        { problem.gatherAndRemap( step ); },
        true );
}

//---------------------------------------------------------------------------//
//! The last point loop: velocity gradient, Mohr-Coulomb stress update,
//! positions and the step's diagnostics. The point state is restored
//! (untimed) after each iteration, so every iteration sees the prepared
//! stresses and yielded points.
template <class ExecSpace>
void BM_pointUpdate( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    problem.stepToPointUpdate();
    PointState<ExecSpace> saved( sim.particles.size() );
    PointState<ExecSpace>::copy( sim.particles, saved );
    problem.space.fence();
    for ( auto _ : state )
    {
        problem.updatePoints();
        problem.space.fence();
        state.PauseTiming();
        PointState<ExecSpace>::copy( saved, sim.particles );
        problem.space.fence();
        state.ResumeTiming();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! One whole MUSL step (Simulation::advance, default duplication), always
//! from the prepared state (restored untimed after each iteration).
template <class ExecSpace>
void BM_step( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    PointState<ExecSpace> saved( sim.particles.size() );
    PointState<ExecSpace>::copy( sim.particles, saved );
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        sim.advance( problem.dt(), problem.settings );
        space.fence();
        state.PauseTiming();
        PointState<ExecSpace>::copy( saved, sim.particles );
        sim.stateChanged();
        space.fence();
        state.ResumeTiming();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! Sizes (cells across the block height) and reporting of every benchmark.
void kernelSizes( benchmark::internal::Benchmark* b )
{
    b->ArgName( "cells_high" )
        ->Arg( 21 )
        ->Arg( 65 )
        ->Arg( 206 )
        ->Unit( benchmark::kMicrosecond )
        ->UseRealTime();
}
void stepSizes( benchmark::internal::Benchmark* b )
{
    kernelSizes( b );
    b->Unit( benchmark::kMillisecond );
}

} // namespace

// clang-format off
// Serial: the single-thread baseline (plain adds, no duplication).
BENCHMARK_TEMPLATE( BM_p2g, Kokkos::Serial, KE::ScatterNonDuplicated )
    ->Name( "p2g/Serial/plain" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2gGridUpdate, Kokkos::Serial, KE::ScatterNonDuplicated )
    ->Name( "p2g_grid_update/Serial/plain" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_g2pRemap, Kokkos::Serial, KE::ScatterNonDuplicated )
    ->Name( "g2p_remap/Serial/plain" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_pointUpdate, Kokkos::Serial )
    ->Name( "point_update/Serial/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_step, Kokkos::Serial )
    ->Name( "step/Serial/plain" )->Apply( stepSizes );

#ifdef KOKKOS_ENABLE_OPENMP
// OpenMP: both scatter strategies for the scatter kernels.
BENCHMARK_TEMPLATE( BM_p2g, Kokkos::OpenMP, KE::ScatterDuplicated )
    ->Name( "p2g/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2g, Kokkos::OpenMP, KE::ScatterNonDuplicated )
    ->Name( "p2g/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2gGridUpdate, Kokkos::OpenMP, KE::ScatterDuplicated )
    ->Name( "p2g_grid_update/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2gGridUpdate, Kokkos::OpenMP, KE::ScatterNonDuplicated )
    ->Name( "p2g_grid_update/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_g2pRemap, Kokkos::OpenMP, KE::ScatterDuplicated )
    ->Name( "g2p_remap/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_g2pRemap, Kokkos::OpenMP, KE::ScatterNonDuplicated )
    ->Name( "g2p_remap/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_pointUpdate, Kokkos::OpenMP )
    ->Name( "point_update/OpenMP/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_step, Kokkos::OpenMP )
    ->Name( "step/OpenMP/duplicated" )->Apply( stepSizes );
#endif
// clang-format on
