#ifndef MPM_BENCH_PROBLEM_HPP
#define MPM_BENCH_PROBLEM_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_p2g.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_update.hpp>
#include <solver/mpm_simulation.hpp>

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace mpm_bench
{
//---------------------------------------------------------------------------//
// The benchmark problem: a 2:1 block of Mohr–Coulomb soil (E = 10 MPa,
// nu = 0.33, rho = 1900 kg/m^3, c = 20 kPa, phi = 20 deg) H = 10 m high on a
// fixed base, with empty grid cells around it (H/2 on both sides and on top).
// The argument of every benchmark is the number of cells across H, n:
// 2 x 2 points per cell, 8 n^2 points (n = 21, 65, 206: 3.5k, 34k, 340k).
//---------------------------------------------------------------------------//

//! Height of the block, m.
constexpr double block_height_m = 10.0;
//! Simulated time of gravity loading before the timed state, s.
constexpr double preload_time_s = 0.03;

//! The case of the soil block with n cells across its height.
mpm::CaseConfig soilBlockCase( const int n );

//! A case of cases/ (no stages if the file cannot be read).
mpm::CaseConfig projectCase( const std::string& file );

//! The step of a case's last stage (the slope's rainfall): its settings
//! and size.
struct StageStep
{
    mpm::StepSettings settings;
    double dt = 0.0; //!< s
};

//! Applies `config`'s last stage to `sim` from its initial state; steps of
//! `courant` times the CFL limit of that state.
template <class ExecSpace>
StageStep applyLastStage( mpm::Simulation<ExecSpace>& sim,
                          const mpm::CaseConfig& config, const double courant )
{
    const mpm::StageConfig& stage = config.stages.back();
    sim.applyStage( stage );
    return {
        { stage.gravity_m_per_s2[0], stage.gravity_m_per_s2[1], stage.damping },
        courant * sim.waveSpeedLimit().dt_limit };
}

//! Runs benchmark b at the block sizes `cells_high` (cells across the
//! block's height), in microseconds of real time.
inline void blockSizes( benchmark::internal::Benchmark* b,
                        std::initializer_list<int> cells_high )
{
    b->ArgName( "cells_high" );
    for ( const int n : cells_high )
        b->Arg( n );
    b->Unit( benchmark::kMicrosecond )->UseRealTime();
}

//! Registers benchmark `run` under `name`, with the sizes and reporting
//! that `apply` sets.
inline void addBenchmark( const std::string& name,
                          void ( *run )( benchmark::State& ),
                          void ( *apply )( benchmark::internal::Benchmark* ) )
{
    benchmark::RegisterBenchmark( name.c_str(), run )->Apply( apply );
}

//! Host copy of the state of the points after the preload.
struct PreparedState
{
    mpm::CaseConfig config;
    double dt = 0.0;           //!< Courant 0.5 x CFL limit of the state, s
    int num_points = 0;        //!< material points
    int preload_steps = 0;     //!< steps taken to reach the state
    double yielded = 0.0;      //!< fraction of points with eps_p_bar > 0
    std::vector<double> x;     //!< x_p
    std::vector<double> x0;    //!< x0_p
    std::vector<double> v;     //!< v_p
    std::vector<double> vol;   //!< vol_p
    std::vector<double> sigma; //!< sigma_p
    std::vector<double> eps;   //!< eps_p
    std::vector<double> eps_p_bar;
    std::vector<int> status;
};

/*!
  \brief The state of the block with n cells across its height: geostatic
  (K0 = nu / (1 - nu)) stresses, then gravity for preload_time_s with the
  step's default backend. Computed once per n and process, kept as host
  vectors (no Views outlive Kokkos::finalize).
*/
const PreparedState& preparedState( const int n );

//---------------------------------------------------------------------------//
//! The fields of ParticleViews that a step changes, for restoring a state.
template <class ExecSpace>
struct PointState
{
    using pv_type = mpm::ParticleViews<ExecSpace>;
    typename pv_type::vector_view x_p, x0_p, v_p;
    typename pv_type::scalar_view vol_p, eps_p_bar_p;
    typename pv_type::tensor_view sigma_p, eps_p;
    typename pv_type::int_view status_p;

    explicit PointState( const int n )
        : x_p( "x_p", n )
        , x0_p( "x0_p", n )
        , v_p( "v_p", n )
        , vol_p( "vol_p", n )
        , eps_p_bar_p( "eps_p_bar_p", n )
        , sigma_p( "sigma_p", n )
        , eps_p( "eps_p", n )
        , status_p( "status_p", n )
    {
    }

    //! Copies every field of `from` into `to` (PointState or ParticleViews).
    template <class From, class To>
    static void copy( const From& from, const To& to )
    {
        Kokkos::deep_copy( to.x_p, from.x_p );
        Kokkos::deep_copy( to.x0_p, from.x0_p );
        Kokkos::deep_copy( to.v_p, from.v_p );
        Kokkos::deep_copy( to.vol_p, from.vol_p );
        Kokkos::deep_copy( to.eps_p_bar_p, from.eps_p_bar_p );
        Kokkos::deep_copy( to.sigma_p, from.sigma_p );
        Kokkos::deep_copy( to.eps_p, from.eps_p );
        Kokkos::deep_copy( to.status_p, from.status_p );
    }
};

//---------------------------------------------------------------------------//
//! Copies a host vector into a View of the same number of entries.
template <class ViewType, class T>
void loadView( const std::vector<T>& values, const ViewType& view )
{
    auto h = Kokkos::create_mirror_view( view );
    for ( std::size_t k = 0; k < values.size(); ++k )
        h.data()[k] = values[k];
    Kokkos::deep_copy( view, h );
}

//---------------------------------------------------------------------------//
/*!
  \brief The block problem on ExecSpace in its prepared state, with the
  phases of the dry MUSL step callable one by one: the kernels
  Simulation::advanceStep<DryScene> runs, in its order, on sums of their own
  (B-bar off, as in the block case), to set up the input of the kernel under
  test.
*/
template <class ExecSpace>
class BlockProblem
{
  public:
    const PreparedState& prepared;
    mpm::Simulation<ExecSpace> sim;
    mpm::StepSettings settings;
    ExecSpace space;
    mpm::DryStepPhases<ExecSpace> phases; //!< the simulation's scatters

    explicit BlockProblem( const int n )
        : prepared( preparedState( n ) )
        , sim( prepared.config )
        , phases( sim.grid.geometry )
    {
        const mpm::StageConfig& stage = prepared.config.stages.front();
        settings.gravity_x = stage.gravity_m_per_s2[0];
        settings.gravity_y = stage.gravity_m_per_s2[1];
        settings.damping = stage.damping;
        const auto& pv = sim.particles;
        loadView( prepared.x, pv.x_p );
        loadView( prepared.x0, pv.x0_p );
        loadView( prepared.v, pv.v_p );
        loadView( prepared.vol, pv.vol_p );
        loadView( prepared.sigma, pv.sigma_p );
        loadView( prepared.eps, pv.eps_p );
        loadView( prepared.eps_p_bar, pv.eps_p_bar_p );
        loadView( prepared.status, pv.status_p );
        space.fence();
    }

    double dt() const { return prepared.dt; }

    //! The phases of the dry step as Simulation::advanceStep<DryScene> runs
    //! them (mpm::DryStepPhases), with the stage's settings; `step` holds the
    //! sums (its scatter strategy).
    template <class Phases>
    void scatter( const Phases& step )
    {
        step.scatter( space, sim.particles, sim.grid.geometry,
                      settings.gravity_x, settings.gravity_y,
                      sim.conditions.load_force );
    }
    template <class Phases>
    void gridUpdate( const Phases& step )
    {
        step.updateGrid( space, sim.grid, dt(), settings.damping,
                         sim.solver.inertia_scaling );
    }
    template <class Phases>
    void gatherAndRemap( const Phases& step )
    {
        step.gatherAndRemap( space, sim.particles, sim.grid, dt(),
                             sim.solver.flip_fraction );
    }
    void updatePoints()
    {
        phases.updatePoints( space, sim.particles, sim.grid, sim.materials,
                             dt(), false,
                             sim.solver.remove_points_leaving_grid );
    }
    //! The phases before the last point loop, with the default sums.
    void stepToPointUpdate()
    {
        scatter( phases );
        gridUpdate( phases );
        gatherAndRemap( phases );
    }

    //! Rate and problem counters of a finished benchmark.
    void setCounters( benchmark::State& state ) const
    {
        const int num_points = sim.numActivePoints();
        state.SetItemsProcessed( state.iterations() * num_points );
        state.counters["points"] = num_points;
        state.counters["threads"] = ExecSpace::concurrency();
        state.counters["grid_nodes"] = sim.grid.geometry.numNodes();
        state.counters["yielded"] = prepared.yielded;
    }
};

} // namespace mpm_bench

#endif // MPM_BENCH_PROBLEM_HPP
