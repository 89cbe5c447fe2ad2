// Checkpoint / restart: a run stopped and continued from its checkpoint
// ends in exactly the state of an uninterrupted run (bitwise on Serial);
// checkpoints of another case are refused; the file is written atomically.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_cli.hpp>

#include <io/mpm_case_fingerprint.hpp>
#include <io/mpm_case_reader.hpp>
#include <io/mpm_checkpoint.hpp>
#include <solver/mpm_checkpoint_state.hpp>
#include <solver/mpm_run_stages.hpp>

#include <hdf5.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

template <class ExecSpace>
class Restart : public ::testing::Test
{
};
TYPED_TEST_SUITE( Restart, mpm_test::Backends, mpm_test::BackendName );

//! Per-process scratch folder (other runs of the suite may be running).
fs::path scratch()
{
    return fs::path( ::testing::TempDir() ) /
           ( "rainslide_restart_" + std::to_string( ::getpid() ) );
}

//! Removes the scratch folder when the test binary exits.
const struct ScratchCleanup
{
    ~ScratchCleanup()
    {
        std::error_code ignored;
        fs::remove_all( scratch(), ignored );
    }
} scratch_cleanup;

fs::path freshDir( const std::string& name )
{
    const fs::path dir = scratch() / name;
    fs::remove_all( dir );
    fs::create_directories( dir );
    return dir;
}

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

    mpm::StageConfig gravity;
    gravity.name = "gravity";
    gravity.type = mpm::StageType::QuasiStatic;
    gravity.damping = 0.7;
    gravity.duration_s = 0.03;
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

//---------------------------------------------------------------------------//
//! Every array of two states: bitwise equal (exact) or within a relative
//! 1e-10 of the array's largest magnitude.
void expectSameState( const mpm::Checkpoint& a, const mpm::Checkpoint& b,
                      const bool exact )
{
    EXPECT_EQ( a.step, b.step );
    EXPECT_EQ( a.num_removed, b.num_removed );
    if ( exact )
        EXPECT_EQ( a.time_s, b.time_s );
    else
        EXPECT_NEAR( a.time_s, b.time_s, 1.0e-10 * a.time_s );
    ASSERT_EQ( a.arrays.size(), b.arrays.size() );
    for ( std::size_t k = 0; k < a.arrays.size(); ++k )
    {
        const mpm::CheckpointArray& x = a.arrays[k];
        const mpm::CheckpointArray& y = b.arrays[k];
        ASSERT_EQ( x.name, y.name );
        ASSERT_EQ( x.dims, y.dims ) << x.name;
        EXPECT_EQ( x.integers, y.integers ) << x.name;
        ASSERT_EQ( x.reals.size(), y.reals.size() ) << x.name;
        double scale = 0.0;
        for ( const double v : x.reals )
            scale = std::max( scale, std::abs( v ) );
        std::size_t differing = 0, first = 0;
        for ( std::size_t i = 0; i < x.reals.size(); ++i )
        {
            const bool same =
                exact ? std::memcmp( &x.reals[i], &y.reals[i],
                                     sizeof( double ) ) == 0
                      : std::abs( x.reals[i] - y.reals[i] ) <= 1.0e-10 * scale;
            if ( !same && differing++ == 0 )
                first = i;
        }
        EXPECT_EQ( differing, 0u )
            << x.name << ": " << differing << " of " << x.reals.size()
            << " values differ, first [" << first
            << "]: " << ( x.reals.empty() ? 0.0 : x.reals[first] ) << " vs "
            << ( y.reals.empty() ? 0.0 : y.reals[first] );
    }
}

//! Run summaries: equal counts, times equal (exact) or within 1e-10.
void expectSameSummary( const mpm::RunSummary& a, const mpm::RunSummary& b,
                        const bool exact )
{
    const auto near = [&]( const double x, const double y, const char* what )
    {
        if ( exact )
            EXPECT_EQ( x, y ) << what;
        else
            EXPECT_NEAR( x, y, 1.0e-10 * std::abs( x ) ) << what;
    };
    EXPECT_EQ( a.steps, b.steps );
    EXPECT_EQ( a.interrupted, b.interrupted );
    near( a.dt_min_s, b.dt_min_s, "dt_min_s" );
    near( a.dt_max_s, b.dt_max_s, "dt_max_s" );
    ASSERT_EQ( a.stages.size(), b.stages.size() );
    for ( std::size_t s = 0; s < a.stages.size(); ++s )
    {
        EXPECT_EQ( a.stages[s].name, b.stages[s].name );
        EXPECT_EQ( a.stages[s].steps, b.stages[s].steps );
        EXPECT_EQ( a.stages[s].converged, b.stages[s].converged );
        near( a.stages[s].duration_s, b.stages[s].duration_s, "duration_s" );
        near( a.stages[s].ke_ratio, b.stages[s].ke_ratio, "ke_ratio" );
    }
}

//! Step and time of the snapshots of `all` from index `from` on.
std::vector<std::pair<long, double>>
marks( const std::vector<mpm::RunProgress>& all, const std::size_t from )
{
    std::vector<std::pair<long, double>> out;
    for ( std::size_t k = from; k < all.size(); ++k )
        out.emplace_back( all[k].step, all[k].time_s );
    return out;
}

//---------------------------------------------------------------------------//
// The checkpoint names every View of the point structs (a View added to
// them must be added to forEachParticleView / forEachWaterParticleView).
TYPED_TEST( Restart, checkpoint_lists_every_point_view )
{
    const mpm::ParticleViews<TypeParam> pv( 1 );
    const mpm::WaterParticleViews<TypeParam> wv( 1 );
    std::size_t bytes = 0;
    const auto add = [&]( const char*, const auto& view )
    { bytes += sizeof( view ); };
    mpm::forEachParticleView( pv, add );
    EXPECT_EQ( bytes, sizeof( pv ) )
        << "a View of ParticleViews is missing in forEachParticleView "
           "(src/solver/mpm_checkpoint_state.hpp)";
    bytes = 0;
    mpm::forEachWaterParticleView( wv, add );
    EXPECT_EQ( bytes, sizeof( wv ) )
        << "a View of WaterParticleViews is missing in "
           "forEachWaterParticleView (src/solver/mpm_checkpoint_state.hpp)";
}

//---------------------------------------------------------------------------//
// Two-phase: stopped in the gravity stage, continued, stopped again in the
// rain stage, continued to the end: the same state, step for step, as an
// uninterrupted run (bitwise on Serial), the same snapshots after each
// checkpoint, the same stage summaries.
TYPED_TEST( Restart, two_phase_restart_matches_uninterrupted_run )
{
    const auto config = twoPhaseCase();
    const bool exact = std::is_same_v<TypeParam, Kokkos::Serial>;
    const fs::path dir = freshDir( "two_phase" );
    const std::string file = ( dir / "checkpoint.h5" ).string();

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
    expectSameSummary( full.summary, part3.summary, exact );
    expectSameState( mpm::captureCheckpoint( full.sim, config, {} ),
                     mpm::captureCheckpoint( part3.sim, config, {} ), exact );

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
    const bool exact = std::is_same_v<TypeParam, Kokkos::Serial>;
    Finished<TypeParam> full( config );
    ASSERT_GE( full.observer.checkpoints.size(), 3u );

    // The third periodic checkpoint; the run went on after it.
    const mpm::Checkpoint& third = full.observer.saved[2];
    EXPECT_GT( third.loop.next_checkpoint_s, third.time_s );

    Finished<TypeParam> resumed( config, &third );
    expectSameSummary( full.summary, resumed.summary, exact );
    expectSameState( mpm::captureCheckpoint( full.sim, config, {} ),
                     mpm::captureCheckpoint( resumed.sim, config, {} ), exact );
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
    const bool exact = std::is_same_v<TypeParam, Kokkos::Serial>;
    const fs::path dir = freshDir( "dry" );
    const std::string file = ( dir / "checkpoint.h5" ).string();

    Finished<TypeParam> full( config );
    const long stop = full.summary.steps / 3;
    ASSERT_GT( stop, 10 );
    Finished<TypeParam> part( config, nullptr, stop, file );
    const mpm::Checkpoint checkpoint = mpm::readCheckpoint( file );
    EXPECT_EQ( checkpoint.identity.analysis, "dry" );
    EXPECT_EQ( checkpoint.find( "water/p_w_p" ), nullptr );
    Finished<TypeParam> resumed( config, &checkpoint );
    expectSameSummary( full.summary, resumed.summary, exact );
    expectSameState( mpm::captureCheckpoint( full.sim, config, {} ),
                     mpm::captureCheckpoint( resumed.sim, config, {} ), exact );
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
//! Every field of a loop state as text (doubles in hex: exact).
std::vector<std::string> loopFields( const mpm::StageLoopState& state )
{
    std::vector<std::string> out;
    const auto text = [&]( const std::string& name, const auto& value )
    {
        using T = std::decay_t<decltype( value )>;
        std::ostringstream line;
        line << name << " = ";
        if constexpr ( std::is_same_v<T, double> )
            line << std::hexfloat << value;
        else
            line << value;
        out.push_back( line.str() );
    };
    mpm::visitStageLoopState(
        state,
        [&]( const std::string& name, const auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<mpm::StageSummary>> )
            {
                for ( std::size_t k = 0; k < value.size(); ++k )
                    mpm::visitStageSummary(
                        value[k], [&]( const std::string& field, const auto& v )
                        { text( name + std::to_string( k ) + field, v ); } );
            }
            else
                text( name, value );
        } );
    return out;
}

// Every field of the loop state survives the file, with distinct values.
TEST( RestartFile, loop_state_round_trips )
{
    mpm::StageLoopState state;
    int k = 0;
    const auto fill = [&]( auto& value )
    {
        using T = std::decay_t<decltype( value )>;
        ++k;
        if constexpr ( std::is_same_v<T, double> )
            value = 1.0 / 3.0 + k;
        else if constexpr ( std::is_same_v<T, std::string> )
            value = "text " + std::to_string( k );
        else if constexpr ( std::is_same_v<T, bool> )
            value = k % 2 == 0;
        else
            value = static_cast<T>( 1000 + k );
    };
    mpm::visitStageLoopState(
        state,
        [&]( const std::string&, auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<mpm::StageSummary>> )
            {
                value.resize( 2 );
                for ( auto& summary : value )
                    mpm::visitStageSummary( summary,
                                            [&]( const std::string&, auto& v )
                                            { fill( v ); } );
            }
            else
                fill( value );
        } );
    mpm::Checkpoint checkpoint;
    checkpoint.loop = state;
    checkpoint.identity.case_fingerprint = "a = 1\n";
    checkpoint.load_groups = { { 0, 2 }, { 1 } };
    checkpoint.load_counts = { 3, 4, 5 };
    checkpoint.snapshots = { 7, 123, 0.25 };
    const fs::path file = freshDir( "round_trip" ) / "checkpoint.h5";
    mpm::writeCheckpoint( file.string(), checkpoint );
    const mpm::Checkpoint read = mpm::readCheckpoint( file.string() );
    EXPECT_EQ( loopFields( read.loop ), loopFields( state ) );
    EXPECT_EQ( read.load_groups, checkpoint.load_groups );
    EXPECT_EQ( read.load_counts, checkpoint.load_counts );
    EXPECT_EQ( read.identity.case_fingerprint, "a = 1\n" );
    EXPECT_EQ( read.snapshots.count, 7 );
    EXPECT_EQ( read.snapshots.last_step, 123 );
}

//---------------------------------------------------------------------------//
// Writing goes through <file>.partial + rename: a failed write leaves the
// previous checkpoint intact and readable.
TEST( RestartFile, failed_write_keeps_the_previous_checkpoint )
{
    const fs::path dir = freshDir( "atomic" );
    const std::string file = ( dir / "checkpoint.h5" ).string();
    mpm::Checkpoint first;
    first.step = 11;
    mpm::writeCheckpoint( file, first );
    EXPECT_FALSE( fs::exists( file + ".partial" ) );
    // A folder in the way of the temporary file makes the next write fail.
    fs::create_directory( file + ".partial" );
    mpm::Checkpoint second;
    second.step = 22;
    EXPECT_THROW( mpm::writeCheckpoint( file, second ), std::runtime_error );
    EXPECT_EQ( mpm::readCheckpoint( file ).step, 11 );
    fs::remove( file + ".partial" );
    mpm::writeCheckpoint( file, second );
    EXPECT_EQ( mpm::readCheckpoint( file ).step, 22 );
    // Not a checkpoint: refused with the file's name.
    std::ofstream( dir / "other.h5" ) << "not hdf5";
    try
    {
        mpm::readCheckpoint( ( dir / "other.h5" ).string() );
        ADD_FAILURE() << "no error";
    }
    catch ( const std::runtime_error& e )
    {
        EXPECT_NE( std::string( e.what() ).find( "other.h5" ),
                   std::string::npos );
    }
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

//! The test block (mpm_test::blockCaseText) with two dynamic stages, the
//! first `duration_s` long.
std::string blockCase( const std::string& solver_extra,
                       const double duration_s = 0.2 )
{
    return mpm_test::blockCaseText( solver_extra, R"(
[[stages]]
name = "load"
type = "dynamic"
duration_s = )" + std::to_string( duration_s ) +
                                                      R"(
snapshot_interval_s = 0.05
[[stages]]
name = "more"
type = "dynamic"
duration_s = 0.1
snapshot_interval_s = 0.05
)" );
}

// The case's keys identify it: a changed value is refused and named; a
// changed checkpoint interval, comment or layout is not a change.
TEST( RestartFile, changed_case_file_is_refused_with_the_key )
{
    const auto original = mpm::parseCase(
        blockCase( "courant_number = 0.5\ncheckpoint_interval_s = 0.1" ),
        "block.toml" );
    const auto reformatted = mpm::parseCase(
        "# a comment\n" +
            blockCase( "checkpoint_interval_s = 0.3\ncourant_number = 0.50" ),
        "block.toml" );
    const auto changed = mpm::parseCase(
        blockCase( "courant_number = 0.4", 0.25 ), "block_v2.toml" );
    EXPECT_EQ( original.fingerprint, reformatted.fingerprint );
    EXPECT_NE( original.fingerprint.find( "stages[1].name = 'more'" ),
               std::string::npos )
        << original.fingerprint;

    mpm::Checkpoint checkpoint;
    checkpoint.identity.case_name = original.name;
    checkpoint.identity.case_file = original.file;
    checkpoint.identity.case_fingerprint = original.fingerprint;
    auto now = checkpoint.identity;
    EXPECT_EQ( mpm::checkpointMismatch( checkpoint, "c.h5", now ), "" );
    now.case_fingerprint = reformatted.fingerprint;
    EXPECT_EQ( mpm::checkpointMismatch( checkpoint, "c.h5", now ), "" );
    now.case_file = changed.file;
    now.case_fingerprint = changed.fingerprint;
    const std::string why = mpm::checkpointMismatch( checkpoint, "c.h5", now );
    for ( const char* fragment :
          { "c.h5", "block.toml", "block_v2.toml",
            "solver.courant_number: 0.5 in the checkpoint, 0.4 now",
            "stages[0].duration_s: 0.2 in the checkpoint, 0.25 now" } )
        EXPECT_NE( why.find( fragment ), std::string::npos ) << fragment << "\n"
                                                             << why;
}

//---------------------------------------------------------------------------//
// The CLI: `run --stop-after-steps` stops like Ctrl-C (checkpoint, exit
// 130, how to resume); `run --restart` continues; the particle file, its
// XDMF and the metrics equal those of an uninterrupted run.
using mpm_test::CommandResult;

CommandResult runCommand( const std::string& args )
{
    return mpm_test::runRainslide( args, scratch() / "cli.log" );
}

std::string readText( const fs::path& file )
{
    std::ifstream in( file );
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

//! Every snapshot of a particle file: "<group>@<attr>" and "<dataset>"
//! -> raw bytes.
std::map<std::string, std::string> snapshotBytes( const fs::path& h5 )
{
    std::map<std::string, std::string> out;
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    if ( file < 0 )
        return out;
    struct Visit
    {
        hid_t file;
        std::map<std::string, std::string>* out;
    } visit{ file, &out };
    const H5O_iterate_t collect = []( hid_t, const char* name,
                                      const H5O_info_t* info,
                                      void* data ) -> herr_t
    {
        auto& v = *static_cast<Visit*>( data );
        const std::string path = std::string( "/snapshots/" ) + name;
        if ( info->type == H5O_TYPE_DATASET )
        {
            const hid_t dset = H5Dopen2( v.file, path.c_str(), H5P_DEFAULT );
            const hid_t type = H5Dget_type( dset );
            const hid_t space = H5Dget_space( dset );
            std::string bytes( H5Sget_simple_extent_npoints( space ) *
                                   H5Tget_size( type ),
                               '\0' );
            if ( !bytes.empty() )
                H5Dread( dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         bytes.data() );
            ( *v.out )[path] = bytes;
            H5Sclose( space );
            H5Tclose( type );
            H5Dclose( dset );
        }
        else if ( info->type == H5O_TYPE_GROUP )
            for ( const char* attr :
                  { "time_s", "stage", "stage_time_s", "step", "n_points" } )
            {
                if ( H5Aexists_by_name( v.file, path.c_str(), attr,
                                        H5P_DEFAULT ) <= 0 )
                    continue;
                const hid_t a = H5Aopen_by_name( v.file, path.c_str(), attr,
                                                 H5P_DEFAULT, H5P_DEFAULT );
                const hid_t type = H5Aget_type( a );
                std::string bytes( H5Tget_size( type ), '\0' );
                H5Aread( a, type, bytes.data() );
                ( *v.out )[path + "@" + attr] = bytes;
                H5Tclose( type );
                H5Aclose( a );
            }
        return 0;
    };
    const hid_t group = H5Gopen2( file, "/snapshots", H5P_DEFAULT );
    H5Ovisit( group, H5_INDEX_NAME, H5_ITER_INC, collect, &visit );
    H5Gclose( group );
    H5Fclose( file );
    return out;
}

void expectSameOutputs( const fs::path& full, const fs::path& resumed )
{
    const auto a = snapshotBytes( full / "particles.h5" );
    const auto b = snapshotBytes( resumed / "particles.h5" );
    EXPECT_GT( a.size(), 50u );
    EXPECT_EQ( a.size(), b.size() );
    for ( const auto& [key, bytes] : a )
    {
        const auto it = b.find( key );
        ASSERT_NE( it, b.end() ) << key;
        EXPECT_TRUE( it->second == bytes ) << key;
    }
    EXPECT_EQ( readText( full / "particles.xdmf" ),
               readText( resumed / "particles.xdmf" ) );
    EXPECT_FALSE( fs::exists( resumed / "particles.h5.partial" ) );
    const auto m_full =
        nlohmann::json::parse( readText( full / "metrics.json" ) );
    const auto m =
        nlohmann::json::parse( readText( resumed / "metrics.json" ) );
    for ( const char* key : { "status", "steps", "simulated_time_s", "stages",
                              "deformation", "dt_s", "dt_min_s" } )
        EXPECT_EQ( m_full[key], m[key] ) << key;
    EXPECT_EQ( m_full["output"]["snapshots"], m["output"]["snapshots"] );
    EXPECT_TRUE( m.contains( "restart" ) );
    EXPECT_GT( m["wall_s"].get<double>(),
               m["restart"]["wall_s_this_session"].get<double>() );
}

TEST( RestartCli, stop_and_restart_give_the_uninterrupted_outputs )
{
    const fs::path dir = freshDir( "cli" );
    const fs::path case_file = dir / "block.toml";
    std::ofstream( case_file ) << blockCase( "checkpoint_interval_s = 0.03" );
    const std::string run =
        "run " + case_file.string() + " --backend serial --quiet --out ";

    ASSERT_EQ( runCommand( run + ( dir / "full" ).string() ).exit_code, 0 );

    // Stopped in the first stage: exit 130, a checkpoint, how to go on.
    const fs::path part = dir / "part";
    auto stopped = runCommand( run + part.string() + " --stop-after-steps 30" );
    EXPECT_EQ( stopped.exit_code, 130 ) << stopped.output;
    EXPECT_NE( stopped.output.find( "checkpoint at step 30" ),
               std::string::npos )
        << stopped.output;
    EXPECT_NE( stopped.output.find( "--restart " +
                                    ( part / "checkpoint.h5" ).string() ),
               std::string::npos )
        << stopped.output;
    EXPECT_EQ(
        nlohmann::json::parse( readText( part / "metrics.json" ) )["status"],
        "interrupted" );
    const fs::path copy = dir / "copy";
    fs::copy( part, copy );

    // Continued in place (--out defaults to the checkpoint's folder).
    auto resumed = runCommand( "run " + case_file.string() +
                               " --backend serial --quiet --restart " +
                               ( part / "checkpoint.h5" ).string() );
    ASSERT_EQ( resumed.exit_code, 0 ) << resumed.output;
    expectSameOutputs( dir / "full", part );

    // Continued into another folder, after a "crash" that left the
    // particle file as .partial (with a snapshot after the checkpoint).
    fs::rename( copy / "particles.h5", copy / "particles.h5.partial" );
    resumed = runCommand( "run " + case_file.string() +
                          " --backend serial --quiet --restart " +
                          ( copy / "checkpoint.h5" ).string() + " --out " +
                          ( dir / "elsewhere" ).string() );
    ASSERT_EQ( resumed.exit_code, 0 ) << resumed.output;
    expectSameOutputs( dir / "full", dir / "elsewhere" );
}

TEST( RestartCli, changed_case_or_missing_snapshots_are_refused )
{
    const fs::path dir = freshDir( "cli_refused" );
    const fs::path case_file = dir / "block.toml";
    std::ofstream( case_file ) << blockCase( "" );
    const fs::path part = dir / "part";
    ASSERT_EQ( runCommand( "run " + case_file.string() +
                           " --backend serial --quiet --stop-after-steps 20 "
                           "--out " +
                           part.string() )
                   .exit_code,
               130 );
    const std::string before = readText( part / "metrics.json" );

    const fs::path changed = dir / "changed.toml";
    std::ofstream( changed ) << blockCase( "", 0.3 );
    auto result =
        runCommand( "run " + changed.string() + " --backend serial --restart " +
                    ( part / "checkpoint.h5" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE(
        result.output.find( "stages[0].duration_s: 0.2 in the checkpoint, 0.3 "
                            "now" ),
        std::string::npos )
        << result.output;
    EXPECT_EQ( readText( part / "metrics.json" ), before );

    fs::remove( part / "particles.h5" );
    result = runCommand( "run " + case_file.string() +
                         " --backend serial --restart " +
                         ( part / "checkpoint.h5" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE( result.output.find( "particles.h5: does not exist" ),
               std::string::npos )
        << result.output;
}

} // namespace
