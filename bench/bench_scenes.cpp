// Cost of one whole step per kind of scene ("model only what a scene
// needs"): dry (single phase), saturated and unsaturated two-phase, on the
// same block of soil. Arg: cells across the block's height (2 x 2 points
// per cell, 8 n^2 points).

#include <bench_problem.hpp>

#include <solver/mpm_run_stages.hpp>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

namespace
{
//! The benchmark block as a scene of the given kind (two-phase: the
//! paper's slope soil, n = 0.3, k = 4.5e-9 m^2; unsaturated: van Genuchten
//! at 20 kPa suction, S ~ 0.3, near the steep part of the curve).
mpm::CaseConfig sceneCase( const int n, const mpm::AnalysisType analysis )
{
    mpm::CaseConfig config = mpm_bench::soilBlockCase( n );
    config.analysis = analysis;
    if ( analysis == mpm::AnalysisType::Dry )
        return config;
    for ( auto* materials : { &config.materials, &config.stages[0].materials } )
        for ( auto& m : *materials )
        {
            m.solid_density_kg_per_m3 = 2700.0;
            m.porosity = 0.3;
            m.permeability_m2 = 4.5e-9;
            if ( analysis == mpm::AnalysisType::Unsaturated )
            {
                m.retention.model = mpm::RetentionType::VanGenuchten;
                m.retention.alpha_per_pa = 4.4e-4;
                m.retention.n = 3.04;
                m.retention.residual_saturation = 0.23;
            }
        }
    for ( auto& body : config.bodies )
        body.initial_pore_pressure_pa =
            analysis == mpm::AnalysisType::Unsaturated ? -2.0e4 : 0.0;
    return config;
}

template <class ExecSpace>
void BM_sceneStep( benchmark::State& state, const mpm::AnalysisType analysis )
{
    const auto config =
        sceneCase( static_cast<int>( state.range( 0 ) ), analysis );
    mpm::Simulation<ExecSpace> sim( config );
    const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };
    // A few steps so the timed state has stresses and flow.
    const double dt = 0.5 * sim.waveSpeedLimit().dt_limit;
    for ( int k = 0; k < 5; ++k )
        sim.advance( dt, settings );
    ExecSpace().fence();
    for ( auto _ : state )
    {
        sim.advance( dt, settings );
        ExecSpace().fence();
    }
    const int num_points = sim.particles.size();
    state.SetItemsProcessed( state.iterations() * num_points );
    state.counters["points"] = num_points;
    state.counters["threads"] = ExecSpace::concurrency();
    state.counters["dt_s"] = dt;
}

template <class ExecSpace>
void BM_stepDry( benchmark::State& state )
{
    BM_sceneStep<ExecSpace>( state, mpm::AnalysisType::Dry );
}
template <class ExecSpace>
void BM_stepSaturated( benchmark::State& state )
{
    BM_sceneStep<ExecSpace>( state, mpm::AnalysisType::Saturated );
}
template <class ExecSpace>
void BM_stepUnsaturated( benchmark::State& state )
{
    BM_sceneStep<ExecSpace>( state, mpm::AnalysisType::Unsaturated );
}

// Names as in bench_kernels.cpp: <scene step>/<backend>/<scatter>/cells_high:n
// (the simulation scatters with duplication on OpenMP).
void sceneSizes( benchmark::internal::Benchmark* b )
{
    b->ArgName( "cells_high" )
        ->Arg( 21 )
        ->Arg( 65 )
        ->Unit( benchmark::kMicrosecond )
        ->UseRealTime();
}

BENCHMARK_TEMPLATE( BM_stepDry, Kokkos::Serial )
    ->Name( "step_dry/Serial/plain" )
    ->Apply( sceneSizes );
BENCHMARK_TEMPLATE( BM_stepSaturated, Kokkos::Serial )
    ->Name( "step_saturated/Serial/plain" )
    ->Apply( sceneSizes );
BENCHMARK_TEMPLATE( BM_stepUnsaturated, Kokkos::Serial )
    ->Name( "step_unsaturated/Serial/plain" )
    ->Apply( sceneSizes );
#ifdef KOKKOS_ENABLE_OPENMP
BENCHMARK_TEMPLATE( BM_stepDry, Kokkos::OpenMP )
    ->Name( "step_dry/OpenMP/duplicated" )
    ->Apply( sceneSizes );
BENCHMARK_TEMPLATE( BM_stepSaturated, Kokkos::OpenMP )
    ->Name( "step_saturated/OpenMP/duplicated" )
    ->Apply( sceneSizes );
BENCHMARK_TEMPLATE( BM_stepUnsaturated, Kokkos::OpenMP )
    ->Name( "step_unsaturated/OpenMP/duplicated" )
    ->Apply( sceneSizes );
#endif

} // namespace
