// The semi-implicit step's pressure passes over the points, on the paper's
// slope (the rainfall stage of cases/slope_base.toml, 4,698 points, after
// 5 semi-implicit steps at the case's Courant number):
// pressure_assembly: what PressureProjection::correct does once a step
// before its Newton iteration (the point terms and their cell sums, the
// nodes' mobility, the cells' stencil); pressure_storage: one Newton
// evaluation of the cells' stored water and its tangent (newtonStorageSums,
// 2.2 a step on the slope). Rates: material points per second.

#include <bench_problem.hpp>

#include <mpm_pressure_newton.hpp>
#include <mpm_pressure_operator.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_stencil_cg.hpp>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

#include <memory>

namespace
{
//! The slope's semi-implicit simulation after 5 steps of rain, the step
//! size it took, and the pressure equation's point terms.
template <class ExecSpace>
struct SlopeAfterRain
{
    std::unique_ptr<mpm::Simulation<ExecSpace>> sim;
    double dt = 0.0;
    mpm::PressurePointTerms<ExecSpace> terms;
    mpm::CellPointLists<ExecSpace> lists;

    //! Leaves `sim` null (and the benchmark skipped) if the case cannot be
    //! read.
    explicit SlopeAfterRain( benchmark::State& state )
    {
        mpm::CaseConfig config = mpm_bench::projectCase( "slope_base.toml" );
        if ( config.stages.empty() )
        {
            state.SkipWithError( "cases/slope_base.toml could not be read" );
            return;
        }
        config.solver.scheme = mpm::TwoPhaseScheme::SemiImplicit;
        sim = std::make_unique<mpm::Simulation<ExecSpace>>( config );
        const mpm_bench::StageStep step = mpm_bench::applyLastStage(
            *sim, config, config.solver.courant_number );
        dt = step.dt;
        for ( int k = 0; k < 5; ++k )
            sim->advance( dt, step.settings );
        terms = mpm::PressurePointTerms<ExecSpace>( sim->grid.geometry );
        lists = mpm::CellPointLists<ExecSpace>( sim->particles.size(),
                                                sim->grid.geometry.nx *
                                                    sim->grid.geometry.ny );
        takePointTerms();
        ExecSpace().fence();
    }

    //! pressurePointTerms (no inflow source): node and cell sums.
    void takePointTerms()
    {
        const auto no_source = KOKKOS_LAMBDA( const int ) { return 0.0; };
        mpm::pressurePointTerms(
            ExecSpace(), sim->particles, sim->water_particles, sim->grid,
            sim->water_grid, sim->water, no_source, lists, terms );
    }

    void report( benchmark::State& state ) const
    {
        state.SetItemsProcessed( state.iterations() * sim->particles.size() );
        state.counters["points"] = sim->particles.size();
        state.counters["threads"] = ExecSpace::concurrency();
    }
};

template <class ExecSpace>
void BM_pressureAssembly( benchmark::State& state )
{
    SlopeAfterRain<ExecSpace> slope( state );
    if ( !slope.sim )
        return;
    const mpm::Simulation<ExecSpace>& sim = *slope.sim;
    const mpm::physics::GridGeometry& grid = sim.grid.geometry;
    const Kokkos::View<double** [2], mpm::DeviceType<ExecSpace>> mu_i(
        "mu_i", grid.nx + 1, grid.ny + 1 );
    mpm::NodeStencilSystem<ExecSpace> system( grid.nx - 1, grid.ny - 1,
                                              grid.nx * grid.ny );
    const ExecSpace space;
    for ( auto _ : state )
    {
        slope.takePointTerms();
        mpm::pressureNodeMobility( space, sim.grid, sim.water_grid, slope.terms,
                                   slope.dt, sim.water.viscosity,
                                   sim.solver.inertia_scaling,
                                   sim.conditions.inflow_flux_i, mu_i );
        mpm::assemblePressureOperator( space, grid, slope.terms, mu_i, system );
        space.fence();
    }
    slope.report( state );
    state.counters["unknowns"] = system.num_nodes;
}

template <class ExecSpace>
void BM_pressureStorage( benchmark::State& state )
{
    SlopeAfterRain<ExecSpace> slope( state );
    if ( !slope.sim )
        return;
    const mpm::Simulation<ExecSpace>& sim = *slope.sim;
    const mpm::physics::GridGeometry& grid = sim.grid.geometry;
    const mpm::NewtonSums<ExecSpace> sums( "newton_sums", grid.nx * grid.ny );
    const bool saturated = sim.analysis == mpm::AnalysisType::Saturated;
    const ExecSpace space;
    for ( auto _ : state )
    {
        mpm::newtonStorageSums( space, sim.particles, sim.water_particles,
                                sim.materials, sim.water, saturated, grid,
                                slope.terms, sim.water_grid.dp_w_c, slope.dt,
                                sums );
        space.fence();
    }
    slope.report( state );
}

void slopeReport( benchmark::internal::Benchmark* b )
{
    b->Unit( benchmark::kMicrosecond )->UseRealTime();
}

//! Registers the pressure benchmarks of one backend as <pass>/<tag>.
template <class Space>
bool addPressurePasses( const std::string& tag )
{
    mpm_bench::addBenchmark( "pressure_assembly/" + tag,
                             BM_pressureAssembly<Space>, slopeReport );
    mpm_bench::addBenchmark( "pressure_storage/" + tag,
                             BM_pressureStorage<Space>, slopeReport );
    return true;
}

const bool serial_passes = addPressurePasses<Kokkos::Serial>( "Serial/plain" );
#ifdef KOKKOS_ENABLE_OPENMP
const bool openmp_passes =
    addPressurePasses<Kokkos::OpenMP>( "OpenMP/duplicated" );
#endif

} // namespace
