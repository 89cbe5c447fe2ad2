// Cost of one whole step per kind of scene ("model only what a scene
// needs"): dry (single phase), saturated and unsaturated two-phase, on the
// same block of soil. Arg: cells across the block's height (2 x 2 points
// per cell, 8 n^2 points). step_*: Simulation::advance; run_step_*: a step
// of runStages (advance and its per-step CFL limit, stability check and
// kinetic energy). run_slope_*: run_step_* on the paper's slope, 4.7k points
// on a mostly empty grid, from rest: cases/slope_total_stress.toml (dry) and
// the rainfall stage of cases/slope_base.toml (unsaturated; semi_implicit:
// with solver.scheme = "semi_implicit" at the case's Courant number).

#include <bench_problem.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <string>

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

//! Times one step of `config` per iteration (after 5 untimed ones),
//! with runStages' per-step calls if `run_step`; steps of `courant` times
//! the CFL limit.
template <class ExecSpace>
void BM_caseSteps( benchmark::State& state, const mpm::CaseConfig& config,
                   const bool run_step, const double courant = 0.5 )
{
    if ( config.stages.empty() )
    {
        state.SkipWithError( "the case file could not be read" );
        return;
    }
    mpm::Simulation<ExecSpace> sim( config );
    const mpm_bench::StageStep stage_step =
        mpm_bench::applyLastStage( sim, config, courant );
    const mpm::StepSettings settings = stage_step.settings;
    const double dt = stage_step.dt;
    double kinetic_energy = 0.0;
    const auto step = [&]()
    {
        if ( !run_step )
        {
            sim.advance( dt, settings );
            return;
        }
        const mpm::WaveSpeedLimit limit = sim.waveSpeedLimit();
        sim.advance( dt, settings );
        sim.checkStability( dt, limit );
        kinetic_energy = sim.kineticEnergy();
        benchmark::DoNotOptimize( sim.numActivePoints() );
    };
    // A few steps so the timed state has stresses and flow.
    for ( int k = 0; k < 5; ++k )
        step();
    ExecSpace().fence();
    for ( auto _ : state )
    {
        step();
        ExecSpace().fence();
    }
    const int num_points = sim.particles.size();
    state.SetItemsProcessed( state.iterations() * num_points );
    state.counters["points"] = num_points;
    state.counters["threads"] = ExecSpace::concurrency();
    state.counters["dt_s"] = dt;
    state.counters["kinetic_energy_j"] = kinetic_energy;
}

/*!
  \brief One step of the block as a scene of kind `analysis`: Simulation::
  advance (run_stage false) or a step of runStages (run_stage true).
*/
template <class ExecSpace, mpm::AnalysisType analysis, bool run_stage>
void BM_sceneStep( benchmark::State& state )
{
    BM_caseSteps<ExecSpace>(
        state, sceneCase( static_cast<int>( state.range( 0 ) ), analysis ),
        run_stage );
}

template <class ExecSpace>
void BM_runSlopeDry( benchmark::State& state )
{
    BM_caseSteps<ExecSpace>(
        state, mpm_bench::projectCase( "slope_total_stress.toml" ), true );
}
template <class ExecSpace>
void BM_runSlopeUnsaturated( benchmark::State& state )
{
    BM_caseSteps<ExecSpace>( state, mpm_bench::projectCase( "slope_base.toml" ),
                             true );
}
template <class ExecSpace>
void BM_runSlopeSemiImplicit( benchmark::State& state )
{
    mpm::CaseConfig config = mpm_bench::projectCase( "slope_base.toml" );
    config.solver.scheme = mpm::TwoPhaseScheme::SemiImplicit;
    BM_caseSteps<ExecSpace>( state, config, true,
                             config.solver.courant_number );
}

// Names as in bench_kernels.cpp: <scene step>/<backend>/<scatter>/cells_high:n
// (the simulation scatters with duplication on OpenMP).
void sceneSizes( benchmark::internal::Benchmark* b )
{
    mpm_bench::blockSizes( b, { 21, 65 } );
}

// ... and the size of the stand-in's refine 10 (bench/standin_ratio.sh).
void threeSceneSizes( benchmark::internal::Benchmark* b )
{
    mpm_bench::blockSizes( b, { 21, 65, 206 } );
}

void slopeReport( benchmark::internal::Benchmark* b )
{
    b->Unit( benchmark::kMicrosecond )->UseRealTime();
}

//! Registers the scene benchmarks of one backend as <scene>/<tag>.
template <class Space>
bool addScenes( const std::string& tag )
{
    using mpm_bench::addBenchmark;
    using A = mpm::AnalysisType;
    addBenchmark( "step_dry/" + tag, BM_sceneStep<Space, A::Dry, false>,
                  sceneSizes );
    addBenchmark( "step_saturated/" + tag,
                  BM_sceneStep<Space, A::Saturated, false>, sceneSizes );
    addBenchmark( "step_unsaturated/" + tag,
                  BM_sceneStep<Space, A::Unsaturated, false>, sceneSizes );
    addBenchmark( "run_step_dry/" + tag, BM_sceneStep<Space, A::Dry, true>,
                  sceneSizes );
    addBenchmark( "run_step_unsaturated/" + tag,
                  BM_sceneStep<Space, A::Unsaturated, true>, threeSceneSizes );
    addBenchmark( "run_slope_dry/" + tag, BM_runSlopeDry<Space>, slopeReport );
    addBenchmark( "run_slope_unsaturated/" + tag, BM_runSlopeUnsaturated<Space>,
                  slopeReport );
    addBenchmark( "run_slope_semi_implicit/" + tag,
                  BM_runSlopeSemiImplicit<Space>, slopeReport );
    return true;
}

const bool serial_scenes = addScenes<Kokkos::Serial>( "Serial/plain" );
#ifdef KOKKOS_ENABLE_OPENMP
const bool openmp_scenes = addScenes<Kokkos::OpenMP>( "OpenMP/duplicated" );
#endif

} // namespace
