// Kernel and step benchmarks of the dry MUSL step on the soil block
// (bench_problem.hpp): the kernels Simulation::advanceStep<DryScene> runs.
// Names: <kernel>/<backend>/<scatter>/cells_high:<n>, scatter = plain (Serial),
// duplicated, atomic (OpenMP non-duplicated) or none (no scatter). Rates
// are material-point updates/s.

#include <bench_problem.hpp>

#include <mpm_scatter.hpp>

#include <array>
#include <string>

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
    mpm_bench::blockSizes( b, { 21, 65, 206 } );
}
void stepSizes( benchmark::internal::Benchmark* b )
{
    kernelSizes( b );
    b->Unit( benchmark::kMillisecond );
}

//! Registers the three scatter kernels of one backend and scatter
//! strategy as <kernel>/<tag>.
template <class Space, class Duplication>
void addScatterKernels( const std::string& tag )
{
    using mpm_bench::addBenchmark;
    addBenchmark( "p2g/" + tag, BM_p2g<Space, Duplication>, kernelSizes );
    addBenchmark( "p2g_grid_update/" + tag,
                  BM_p2gGridUpdate<Space, Duplication>, kernelSizes );
    addBenchmark( "g2p_remap/" + tag, BM_g2pRemap<Space, Duplication>,
                  kernelSizes );
}

/*!
  \brief Registers every kernel benchmark of one backend: the scatter
  kernels with each scatter strategy (`tags` names them), the point update
  and the step (whose scatter `step_tag` names).
*/
template <class Space, class... Duplications>
bool addKernels(
    const std::string& backend, const std::string& step_tag,
    const std::array<const char*, sizeof...( Duplications )>& tags )
{
    int k = 0;
    ( addScatterKernels<Space, Duplications>( backend + "/" + tags[k++] ),
      ... );
    mpm_bench::addBenchmark( "point_update/" + backend + "/none",
                             BM_pointUpdate<Space>, kernelSizes );
    mpm_bench::addBenchmark( "step/" + backend + "/" + step_tag, BM_step<Space>,
                             stepSizes );
    return true;
}

// Serial: the single-thread baseline (plain adds, no duplication).
const bool serial_kernels =
    addKernels<Kokkos::Serial, KE::ScatterNonDuplicated>( "Serial", "plain",
                                                          { "plain" } );
#ifdef KOKKOS_ENABLE_OPENMP
// OpenMP: both scatter strategies for the scatter kernels.
const bool openmp_kernels =
    addKernels<Kokkos::OpenMP, KE::ScatterDuplicated, KE::ScatterNonDuplicated>(
        "OpenMP", "duplicated", { "duplicated", "atomic" } );
#endif
} // namespace
