// Checkpoint / restart of a run: stopped and continued from its checkpoint
// it ends in exactly the state of an uninterrupted run (bitwise on Serial);
// a checkpoint of another case is refused.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_restart.hpp>

#include <io/mpm_case_reader.hpp>
#include <io/mpm_checkpoint.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

namespace
{
namespace fs = std::filesystem;

MPM_TEST_BACKEND_SUITE( Restart );

using namespace mpm_test::restart;

//---------------------------------------------------------------------------//
/*!
  An unsaturated Mohr–Coulomb block (1 m x 1 m, 4 x 4 cells of 2 x 2
  points, free sides, fixed base) at 20 kPa suction: a quasi-static
  gravity stage, then a dynamic "rain" stage with a ponding inflow on the
  surface cells and a ramped load on the top points, both selected at the
  stage start. B-bar on, checkpoints every 6 ms. About 100 steps per
  stage.
*/
mpm::CaseConfig twoPhaseCase()
{
    mpm::MaterialConfig soil =
        mpm_test::saturatedMaterial( 1.0e7, 0.3, 2650.0, 0.3, 1.0e-10 );
    soil.model = mpm::ModelType::MohrCoulomb;
    soil.cohesion_peak_pa = 3.0e3;
    soil.cohesion_residual_pa = 1.0e3;
    soil.softening_modulus_pa = -1.0e5;
    soil.friction_angle_deg = 20.0;
    soil = mpm_test::withPaperRetention( soil );

    mpm::CaseConfig c;
    c.file = "<two-phase test>";
    c.name = "wet_block";
    c.analysis = mpm::AnalysisType::Unsaturated;
    c.water.bulk_modulus_pa = 2.0e8;
    c.grid.origin_m = { 0.0, 0.0 };
    c.grid.cell_size_m = 0.25;
    c.grid.cells = { 8, 6 };
    c.materials = { soil };
    mpm::BodyConfig body;
    body.material = soil.name;
    body.polygon_m = { { 0.5, 0.0 }, { 1.5, 0.0 }, { 1.5, 1.0 }, { 0.5, 1.0 } };
    body.initial_pore_pressure_pa = -2.0e4;
    c.bodies = { body };
    mpm::BoundaryConfig bottom;
    bottom.where = mpm::BoundarySelector::Bottom;
    bottom.condition = mpm::BoundaryCondition::Fixed;
    c.boundaries = { bottom };
    c.solver.bbar = true;
    c.solver.checkpoint_interval_s = 6.0e-3;

    mpm::StageConfig gravity = mpm_test::stageConfig(
        "gravity", mpm::StageType::QuasiStatic, 0.03, -9.81, 0.7 );
    gravity.snapshot_interval_s = 0.01;
    gravity.reset_displacement = true;
    gravity.materials = c.materials;
    gravity.boundaries = c.boundaries;

    mpm::StageConfig rain = gravity;
    rain.name = "rain";
    rain.type = mpm::StageType::Dynamic;
    rain.damping = 0.0;
    rain.reset_displacement = false;
    rain.snapshot_interval_s = 0.0;
    rain.snapshot_times_s = { 4.0e-3, 1.7e-2 };
    mpm::WaterInflow inflow;
    inflow.points.kind = mpm::PointSelection::Kind::SurfaceCells;
    inflow.flux_m_per_s = 1.0e-3;
    inflow.length_m = 1.0;
    inflow.ponding = true;
    rain.inflows = { inflow };
    mpm::PointLoad load;
    load.points.kind = mpm::PointSelection::Kind::Box;
    load.points.box_m = { mpm::Point2{ 0.9, 0.8 }, mpm::Point2{ 1.5, 1.0 } };
    load.traction_pa = { 0.0, -4.0e4 };
    load.length_m = 0.6;
    load.time_function = { { 0.0, 0.0 }, { 0.015, 1.0 } };
    rain.loads = { load };
    c.stages = { gravity, rain };
    return c;
}

//! The dry slope of cases/ cut short: Mohr–Coulomb with softening, one
//! quasi-static stage; checkpoints every 0.05 s.
mpm::CaseConfig dryCase()
{
    auto config =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_total_stress.toml" );
    config.stages.resize( 1 );
    config.stages[0].duration_s = 0.3;
    config.stages[0].snapshot_interval_s = 0.1;
    config.solver.checkpoint_interval_s = 0.05;
    return config;
}

//---------------------------------------------------------------------------//
//! Records snapshots and stage ends; stops after `stop_after` steps and
//! writes every checkpoint to `checkpoint_file`, like the CLI does.
class Recorder : public mpm::RunObserver
{
  public:
    void onStep( const mpm::RunProgress& ) override { ++steps; }
    void onSnapshot( const mpm::RunProgress& progress,
                     const mpm::HostSnapshot& snapshot ) override
    {
        snapshots.push_back( progress );
        last = snapshot;
    }
    bool stopRequested() override
    {
        return stop_after > 0 && steps >= stop_after;
    }
    void onCheckpoint( mpm::Checkpoint& checkpoint ) override
    {
        checkpoint.snapshots.count =
            earlier_snapshots + static_cast<long>( snapshots.size() );
        if ( !snapshots.empty() )
        {
            checkpoint.snapshots.last_step = snapshots.back().step;
            checkpoint.snapshots.last_time_s = snapshots.back().time_s;
        }
        if ( !checkpoint_file.empty() )
            mpm::writeCheckpoint( checkpoint_file, checkpoint );
        checkpoints.push_back( checkpoint.step );
        saved.push_back( checkpoint );
    }

    long stop_after = 0;
    long steps = 0;
    long earlier_snapshots = 0; //!< written before the resumed checkpoint
    std::string checkpoint_file;
    std::vector<long> checkpoints;      //!< step of each checkpoint
    std::vector<mpm::Checkpoint> saved; //!< each checkpoint
    std::vector<mpm::RunProgress> snapshots;
    mpm::HostSnapshot last;
};

//! Runs `config` to the end from `checkpoint` (or from the start).
template <class ExecSpace>
struct Finished
{
    explicit Finished( const mpm::CaseConfig& config,
                       const mpm::Checkpoint* checkpoint = nullptr,
                       const long stop_after = 0,
                       const std::string& checkpoint_file = "" )
        : sim( config )
    {
        observer.stop_after = stop_after;
        observer.checkpoint_file = checkpoint_file;
        if ( checkpoint )
        {
            EXPECT_EQ( mpm::checkpointMismatch(
                           *checkpoint, "<file>",
                           mpm::checkpointIdentity( config, sim ) ),
                       "" );
            mpm::restoreCheckpoint( sim, config, *checkpoint );
            observer.earlier_snapshots = checkpoint->snapshots.count;
            summary = mpm::runStages( sim, config, observer, checkpoint->loop );
        }
        else
            summary = mpm::runStages( sim, config, observer );
    }
    mpm::Simulation<ExecSpace> sim;
    Recorder observer;
    mpm::RunSummary summary;
};

//! Whether runs on ExecSpace repeat bit for bit (Serial).
template <class ExecSpace>
constexpr bool bitwise = std::is_same_v<ExecSpace, Kokkos::Serial>;

//! The checkpoint file of a fresh scratch folder `name`.
std::string checkpointFile( const std::string& name )
{
    return ( freshDir( name ) / "checkpoint.h5" ).string();
}

//! Expects `resumed` to end as `full` did: the same summary and final
//! state (bitwise if `exact`).
template <class ExecSpace>
void expectSameEnd( Finished<ExecSpace>& full, Finished<ExecSpace>& resumed,
                    const mpm::CaseConfig& config, const bool exact )
{
    expectSameSummary( full.summary, resumed.summary, exact );
    expectSameState( mpm::captureCheckpoint( full.sim, config, {} ),
                     mpm::captureCheckpoint( resumed.sim, config, {} ), exact );
}

//---------------------------------------------------------------------------//
// The checkpoint names every View of the point structs (a View added to
// them must be added to their struct's forEachViewOf).
TYPED_TEST( Restart, checkpoint_lists_every_point_view )
{
    const mpm::ParticleViews<TypeParam> pv( 1 );
    const mpm::WaterParticleViews<TypeParam> wv( 1 );
    std::size_t bytes = 0;
    const auto add = [&]( const char*, const auto& view )
    { bytes += sizeof( view ); };
    mpm::forEachView( pv, add );
    EXPECT_EQ( bytes, sizeof( pv ) )
        << "a View of ParticleViews is missing in ParticleViews::forEachViewOf "
           "(views/mpm_particle_views.hpp)";
    bytes = 0;
    mpm::forEachView( wv, add );
    EXPECT_EQ( bytes, sizeof( wv ) )
        << "a View of WaterParticleViews is missing in "
           "WaterParticleViews::forEachViewOf (views/mpm_water_views.hpp)";
}

//---------------------------------------------------------------------------//
// Two-phase: stopped in the gravity stage, continued, stopped again in the
// rain stage, continued to the end: the same state, step for step, as an
// uninterrupted run (bitwise on Serial), the same snapshots after each
// checkpoint, the same stage summaries.
TYPED_TEST( Restart, two_phase_restart_matches_uninterrupted_run )
{
    const auto config = twoPhaseCase();
    const bool exact = bitwise<TypeParam>;
    const std::string file = checkpointFile( "two_phase" );

    Finished<TypeParam> full( config );
    const auto& stages = full.summary.stages;
    ASSERT_EQ( stages.size(), 2u );
    // Enough steps in each stage and some plastic yielding, or this tests
    // little.
    EXPECT_GT( stages[0].steps, 50 );
    EXPECT_GT( stages[1].steps, 50 );
    double eps_max = 0.0;
    for ( const double e : full.observer.last.eps_p_bar )
        eps_max = std::max( eps_max, e );
    EXPECT_GT( eps_max, 0.0 );
    EXPECT_GE( full.observer.checkpoints.size(), 4u );

    // Stop in the gravity stage.
    const long first_stop = stages[0].steps / 2;
    Finished<TypeParam> part1( config, nullptr, first_stop, file );
    EXPECT_TRUE( part1.summary.interrupted );
    ASSERT_FALSE( part1.observer.checkpoints.empty() );
    EXPECT_EQ( part1.observer.checkpoints.back(), first_stop );
    const mpm::Checkpoint checkpoint1 = mpm::readCheckpoint( file );
    EXPECT_EQ( checkpoint1.step, first_stop );
    EXPECT_EQ( checkpoint1.loop.stage, 0u );
    EXPECT_FALSE( fs::exists( file + ".partial" ) );

    // Continue, stop again in the rain stage.
    const long second_stop = stages[0].steps + stages[1].steps / 2 - first_stop;
    Finished<TypeParam> part2( config, &checkpoint1, second_stop, file );
    EXPECT_TRUE( part2.summary.interrupted );
    const mpm::Checkpoint checkpoint2 = mpm::readCheckpoint( file );
    EXPECT_EQ( checkpoint2.step, first_stop + second_stop );
    EXPECT_EQ( checkpoint2.loop.stage, 1u );
    EXPECT_EQ( checkpoint2.loop.run.stages.size(), 1u );

    // Continue to the end.
    Finished<TypeParam> part3( config, &checkpoint2 );
    EXPECT_FALSE( part3.summary.interrupted );
    expectSameEnd( full, part3, config, exact );

    // The snapshots after each checkpoint are those of the full run (the
    // last one of a stopped run is at the stop: not part of the series).
    const auto& all = full.observer.snapshots;
    auto before_stop = marks( part2.observer.snapshots, 0 );
    before_stop.pop_back();
    EXPECT_EQ( checkpoint2.snapshots.count,
               checkpoint1.snapshots.count + long( before_stop.size() ) );
    auto expected = marks( all, checkpoint1.snapshots.count );
    expected.resize( before_stop.size() );
    EXPECT_EQ( expected, before_stop );
    EXPECT_EQ( marks( all, checkpoint2.snapshots.count ),
               marks( part3.observer.snapshots, 0 ) );
}

//---------------------------------------------------------------------------//
// A periodic checkpoint (the run went on after it) continues exactly too.
TYPED_TEST( Restart, periodic_checkpoint_continues_exactly )
{
    const auto config = twoPhaseCase();
    const bool exact = bitwise<TypeParam>;
    Finished<TypeParam> full( config );
    ASSERT_GE( full.observer.checkpoints.size(), 3u );

    // The third periodic checkpoint; the run went on after it.
    const mpm::Checkpoint& third = full.observer.saved[2];
    EXPECT_GT( third.loop.next_checkpoint_s, third.time_s );

    Finished<TypeParam> resumed( config, &third );
    expectSameEnd( full, resumed, config, exact );
    // The resumed run writes the later periodic checkpoints again.
    const auto& steps = full.observer.checkpoints;
    EXPECT_EQ( std::vector<long>( steps.begin() + 3, steps.end() ),
               resumed.observer.checkpoints );
}

//---------------------------------------------------------------------------//
// Dry (Mohr–Coulomb slope): stopped, continued, the same final state.
TYPED_TEST( Restart, dry_restart_matches_uninterrupted_run )
{
    const auto config = dryCase();
    const bool exact = bitwise<TypeParam>;
    const std::string file = checkpointFile( "dry" );

    Finished<TypeParam> full( config );
    const long stop = full.summary.steps / 3;
    ASSERT_GT( stop, 10 );
    Finished<TypeParam> part( config, nullptr, stop, file );
    const mpm::Checkpoint checkpoint = mpm::readCheckpoint( file );
    EXPECT_EQ( checkpoint.identity.analysis, "dry" );
    EXPECT_EQ( checkpoint.find( "water/p_w_p" ), nullptr );
    Finished<TypeParam> resumed( config, &checkpoint );
    expectSameEnd( full, resumed, config, exact );
}

//---------------------------------------------------------------------------//
// The points a stage's conditions apply to come from the checkpoint, not
// from a new selection at the restored positions.
TYPED_TEST( Restart, stage_conditions_come_from_the_checkpoint )
{
    const auto config = twoPhaseCase();
    Finished<TypeParam> full( config );
    Finished<TypeParam> part( config, nullptr,
                              full.summary.stages[0].steps + 10 );
    mpm::Checkpoint checkpoint = part.observer.saved.back();
    ASSERT_EQ( checkpoint.loop.stage, 1u );
    ASSERT_TRUE( checkpoint.loop.stage_started );
    // Mark one point as the only one fed and loaded, with made-up totals.
    for ( auto& a : checkpoint.arrays )
        if ( a.name == "water/inflow_p" || a.name == "particles/load_p" )
        {
            std::fill( a.integers.begin(), a.integers.end(), -1 );
            a.integers[5] = 0;
        }
    checkpoint.inflow_volumes = { 42.0 };
    checkpoint.load_counts = { 1 };
    checkpoint.load_groups = { { 0 } };

    mpm::Simulation<TypeParam> sim( config );
    mpm::restoreCheckpoint( sim, config, checkpoint );
    const auto inflow = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), sim.water_particles.inflow_p );
    const auto load = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), sim.particles.load_p );
    int fed = 0, loaded = 0;
    for ( int p = 0; p < sim.particles.size(); ++p )
    {
        fed += inflow( p ) >= 0;
        loaded += load( p ) >= 0;
    }
    EXPECT_EQ( fed, 1 );
    EXPECT_EQ( loaded, 1 );
    EXPECT_EQ( inflow( 5 ), 0 );
    EXPECT_EQ( sim.conditions.inflow_volumes, std::vector<double>{ 42.0 } );
    EXPECT_EQ( sim.conditions.load_counts, std::vector<int>{ 1 } );
    EXPECT_EQ( sim.conditions.load_force.extent( 0 ), 1u );
}

//---------------------------------------------------------------------------//
// A checkpoint of another case is refused, naming what differs.
TYPED_TEST( Restart, checkpoint_of_another_case_is_refused )
{
    const auto wet = twoPhaseCase();
    Finished<TypeParam> part( wet, nullptr, 5 );
    const mpm::Checkpoint& checkpoint = part.observer.saved.back();

    auto dry = dryCase();
    dry.file = "slope_total_stress.toml";
    mpm::Simulation<TypeParam> sim( dry );
    const std::string why = mpm::checkpointMismatch(
        checkpoint, "run/checkpoint.h5", mpm::checkpointIdentity( dry, sim ) );
    for ( const char* fragment :
          { "run/checkpoint.h5", "<two-phase test>", "slope_total_stress.toml",
            "case name: 'wet_block' in the checkpoint",
            "case.analysis: unsaturated in the checkpoint, dry now",
            "number of material points: 64 in the checkpoint" } )
        EXPECT_NE( why.find( fragment ), std::string::npos ) << fragment << "\n"
                                                             << why;
}

} // namespace
