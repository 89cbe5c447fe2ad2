// Kernel and step benchmarks of the dry MUSL step on the soil block
// (bench_problem.hpp). Names: <kernel>/<backend>/<scatter>/cells_high:<n>,
// scatter = plain (Serial), duplicated, atomic (OpenMP non-duplicated) or
// none (kernels without a scatter). Rates are material-point updates/s.

#include <bench_problem.hpp>

#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_p2g.hpp>
#include <mpm_scatter.hpp>
#include <mpm_stress_update.hpp>
#include <mpm_velocity_gradient.hpp>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

namespace
{
namespace KE = Kokkos::Experimental;
using mpm_bench::BlockProblem;
using mpm_bench::PointState;

//---------------------------------------------------------------------------//
//! P2G scatter of mass, momentum and force.
template <class ExecSpace, class Duplication>
void BM_p2g( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        mpm::p2gMassMomentumForce<ExecSpace, Duplication>(
            space, sim.particles, sim.grid, problem.settings.gravity_x,
            problem.settings.gravity_y, sim.conditions.load_force );
        space.fence();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! The fixed cost of the stand-alone P2G without its point loop: the sums
//! allocated (for Duplicated, one zeroed copy of the packed node fields
//! per thread), the grid fields reset and the touched nodes listed. The
//! time loop keeps its sums between steps and skips the first two.
template <class ExecSpace, class Duplication>
void BM_p2gScatterOverhead( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& gv = problem.sim.grid;
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        const mpm::DryNodeSums<ExecSpace, Duplication> sums(
            "p2g_sums", gv.geometry.numNodes() );
        Kokkos::deep_copy( space, gv.m_i, 0.0 );
        Kokkos::deep_copy( space, gv.p_i, 0.0 );
        Kokkos::deep_copy( space, gv.f_i, 0.0 );
        gv.num_active = sums.listTouched( space, gv.active_i );
        space.fence();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! MUSL remap: momentum scatter and the remapped nodal velocity.
template <class ExecSpace, class Duplication>
void BM_remap( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    problem.scatter();
    problem.gridUpdate();
    problem.g2p();
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        mpm::p2gMomentum<ExecSpace, Duplication>( space, sim.particles,
                                                  sim.grid );
        mpm::remapVelocity( space, sim.grid );
        space.fence();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! Grid update: active-node compaction and the nodal velocity update.
template <class ExecSpace>
void BM_gridUpdate( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    problem.scatter();
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        mpm::findActiveNodes( space, sim.grid );
        mpm::gridUpdateDry( space, sim.grid, problem.dt(),
                            problem.settings.damping,
                            sim.solver.inertia_scaling );
        space.fence();
    }
    problem.setCounters( state );
    state.counters["active_nodes"] = sim.grid.num_active;
}

//---------------------------------------------------------------------------//
//! G2P velocity update. Repeating it from the same grid is a contraction
//! of v_p (FLIP fraction < 1), so the state stays bounded: no restore.
template <class ExecSpace>
void BM_g2p( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    problem.scatter();
    problem.gridUpdate();
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        mpm::g2pVelocity( space, sim.particles, sim.grid, problem.dt(),
                          sim.solver.flip_fraction );
        space.fence();
    }
    problem.setCounters( state );
}

//---------------------------------------------------------------------------//
//! Stress update: velocity gradient and the constitutive update. The
//! point state is restored (untimed) after each iteration, so every
//! iteration sees the prepared stresses and yielded points.
template <class ExecSpace>
void BM_stressUpdate( benchmark::State& state )
{
    BlockProblem<ExecSpace> problem( static_cast<int>( state.range( 0 ) ) );
    auto& sim = problem.sim;
    problem.scatter();
    problem.gridUpdate();
    problem.g2p();
    problem.remap();
    PointState<ExecSpace> saved( sim.particles.size() );
    PointState<ExecSpace>::copy( sim.particles, saved );
    const ExecSpace space;
    space.fence();
    for ( auto _ : state )
    {
        mpm::velocityGradient( space, sim.particles, sim.grid );
        mpm::stressUpdate( space, sim.particles, sim.materials, problem.dt() );
        space.fence();
        state.PauseTiming();
        PointState<ExecSpace>::copy( saved, sim.particles );
        space.fence();
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
BENCHMARK_TEMPLATE( BM_p2gScatterOverhead, Kokkos::Serial,
                    KE::ScatterNonDuplicated )
    ->Name( "p2g_overhead/Serial/plain" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_gridUpdate, Kokkos::Serial )
    ->Name( "grid_update/Serial/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_g2p, Kokkos::Serial )
    ->Name( "g2p/Serial/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_remap, Kokkos::Serial, KE::ScatterNonDuplicated )
    ->Name( "remap/Serial/plain" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_stressUpdate, Kokkos::Serial )
    ->Name( "stress_update/Serial/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_step, Kokkos::Serial )
    ->Name( "step/Serial/plain" )->Apply( stepSizes );

#ifdef KOKKOS_ENABLE_OPENMP
// OpenMP: both scatter strategies for the scatter kernels.
BENCHMARK_TEMPLATE( BM_p2g, Kokkos::OpenMP, KE::ScatterDuplicated )
    ->Name( "p2g/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2g, Kokkos::OpenMP, KE::ScatterNonDuplicated )
    ->Name( "p2g/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2gScatterOverhead, Kokkos::OpenMP,
                    KE::ScatterDuplicated )
    ->Name( "p2g_overhead/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_p2gScatterOverhead, Kokkos::OpenMP,
                    KE::ScatterNonDuplicated )
    ->Name( "p2g_overhead/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_gridUpdate, Kokkos::OpenMP )
    ->Name( "grid_update/OpenMP/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_g2p, Kokkos::OpenMP )
    ->Name( "g2p/OpenMP/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_remap, Kokkos::OpenMP, KE::ScatterDuplicated )
    ->Name( "remap/OpenMP/duplicated" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_remap, Kokkos::OpenMP, KE::ScatterNonDuplicated )
    ->Name( "remap/OpenMP/atomic" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_stressUpdate, Kokkos::OpenMP )
    ->Name( "stress_update/OpenMP/none" )->Apply( kernelSizes );
BENCHMARK_TEMPLATE( BM_step, Kokkos::OpenMP )
    ->Name( "step/OpenMP/duplicated" )->Apply( stepSizes );
#endif
// clang-format on
