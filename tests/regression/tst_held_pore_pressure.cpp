// A tabulated initial pore-pressure profile held through a gravity stage
// ([[stages.pore_pressures]] hold = "initial"), also across a checkpoint.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <io/mpm_checkpoint.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
MPM_TEST_BACKEND_SUITE( HeldPorePressure );

//! Two segments: hydrostatic below the water table at y = 1 m, a suction
//! growing three times as fast above it (not in equilibrium).
const std::vector<std::array<double, 2>> profile = {
    { 0.0, 9810.0 }, { 1.0, 0.0 }, { 2.0, -29430.0 } };

//! The profile at height y, worked out here: 9810 (1 - y) below 1 m,
//! -29430 (y - 1) above.
double profileAt( const double y )
{
    const double h = std::min( std::max( y, 0.0 ), 2.0 );
    return h <= 1.0 ? 9810.0 * ( 1.0 - h ) : -29430.0 * ( h - 1.0 );
}

/*!
  A 2 m unsaturated column of the paper's soil (8 cells of 0.25 m, 2 x 2
  points each) starting on the profile, through a quasi-static gravity
  stage of at most 0.4 s; with `hold`, the points selected by `where`
  (every point, or the box below y = 1 m) hold their p_w.
*/
mpm::CaseConfig heldColumn( const bool hold,
                            const mpm::PointSelection::Kind where )
{
    mpm::StageConfig gravity;
    gravity.name = "gravity";
    gravity.type = mpm::StageType::QuasiStatic;
    gravity.damping = 0.7;
    gravity.duration_s = 0.4;
    auto config =
        mpm_test::columnCase( 2.0, 0.25, mpm_test::paperSoil(), gravity );
    config.analysis = mpm::AnalysisType::Unsaturated;
    config.water.bulk_modulus_pa = 2.0e8;
    config.bodies[0].initial_pore_pressure_profile = profile;
    if ( hold )
    {
        mpm::PorePressureCondition held;
        held.points.kind = where;
        held.points.box_m = { mpm::Point2{ -1.0, -1.0 },
                              mpm::Point2{ 1.0, 1.0 } };
        held.hold_initial = true;
        config.stages[0].pore_pressures = { held };
    }
    return config;
}

//! Largest |p_w - profile(y0)| over the points, y0 their initial heights.
double largestDeparture( const mpm::HostSnapshot& snap,
                         const std::vector<double>& x0, const bool below_only )
{
    double worst = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
        if ( !below_only || x0[2 * p + 1] <= 1.0 )
            worst = std::max(
                worst, std::abs( snap.p_w[p] - profileAt( x0[2 * p + 1] ) ) );
    return worst;
}

//! Records checkpoints (to a file, if named) and stops after stop_after.
class Stopper : public mpm::RunObserver
{
  public:
    void onStep( const mpm::RunProgress& ) override { ++steps; }
    bool stopRequested() override
    {
        return stop_after > 0 && steps >= stop_after;
    }
    void onCheckpoint( mpm::Checkpoint& checkpoint ) override
    {
        if ( !file.empty() )
            mpm::writeCheckpoint( file, checkpoint );
    }
    long stop_after = 0;
    long steps = 0;
    std::string file;
};

//---------------------------------------------------------------------------//
// The points start on the profile; held, every point ends the stage on
// it (at its initial height) while the skeleton settles; not held, the
// water moves.
TYPED_TEST( HeldPorePressure, profile_is_held_through_a_gravity_stage )
{
    const auto config = heldColumn( true, mpm::PointSelection::Kind::All );
    mpm::Simulation<TypeParam> sim( config );
    const auto start = mpm::hostSnapshot( sim );
    const std::vector<double> x0 = start.x;
    EXPECT_LE( largestDeparture( start, x0, false ), 1.0e-11 * 29430.0 );

    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    EXPECT_GT( summary.stages[0].steps, 100 );
    const auto end = mpm::hostSnapshot( sim );
    // The skeleton settled (top points moved down by more than 0.1 mm) ...
    double settlement = 0.0;
    for ( int p = 0; p < end.num_points; ++p )
        settlement = std::max( settlement, -end.displacement[2 * p + 1] );
    EXPECT_GT( settlement, 1.0e-4 );
    // ... and every point kept its p_w to round-off.
    EXPECT_LE( largestDeparture( end, x0, false ), 1.0e-11 * 29430.0 );

    // Without the hold the profile does not stay.
    const auto free_config =
        heldColumn( false, mpm::PointSelection::Kind::All );
    mpm::Simulation<TypeParam> free_sim( free_config );
    mpm::runStages( free_sim, free_config, observer );
    const double held = largestDeparture( end, x0, false );
    const double free =
        largestDeparture( mpm::hostSnapshot( free_sim ), x0, false );
    std::printf( "[ held ] settlement %.3e m, held points off the profile by "
                 "%.2e Pa, free points by %.3e Pa\n",
                 settlement, held, free );
    EXPECT_GT( free, 100.0 );
}

//---------------------------------------------------------------------------//
// Held below y = 1 m only, stopped halfway through the stage, continued
// from the checkpoint file: the held points stay on the profile and the
// state is that of the uninterrupted run (bitwise on Serial). A held value
// changed in the checkpoint is what the continued run holds: the values
// come from the checkpoint, not from the pressures at the restart.
TYPED_TEST( HeldPorePressure, held_values_survive_a_restart )
{
    const auto config = heldColumn( true, mpm::PointSelection::Kind::Box );
    const bool exact = std::is_same_v<TypeParam, Kokkos::Serial>;
    mpm::Simulation<TypeParam> full( config );
    const std::vector<double> x0 = mpm::hostSnapshot( full ).x;
    Stopper none;
    const auto summary = mpm::runStages( full, config, none );
    const long steps = summary.stages[0].steps;
    ASSERT_GT( steps, 100 );

    const std::filesystem::path dir =
        std::filesystem::path( ::testing::TempDir() ) /
        ( "rainslide_held_" + std::to_string( ::getpid() ) );
    std::filesystem::create_directories( dir );
    Stopper stopper;
    stopper.stop_after = steps / 2;
    stopper.file = ( dir / "checkpoint.h5" ).string();
    mpm::Simulation<TypeParam> first( config );
    EXPECT_TRUE( mpm::runStages( first, config, stopper ).interrupted );
    const mpm::Checkpoint checkpoint = mpm::readCheckpoint( stopper.file );
    std::filesystem::remove_all( dir );
    ASSERT_NE( checkpoint.find( "water/p_w_held_p" ), nullptr );

    mpm::Simulation<TypeParam> resumed( config );
    mpm::restoreCheckpoint( resumed, config, checkpoint );
    mpm::runStages( resumed, config, none, checkpoint.loop );
    const auto end = mpm::hostSnapshot( resumed );
    EXPECT_LE( largestDeparture( end, x0, true ), 1.0e-11 * 29430.0 );
    // The free points above did move away from the profile.
    EXPECT_GT( largestDeparture( end, x0, false ), 100.0 );
    const auto a = mpm::captureCheckpoint( full, config, {} );
    const auto b = mpm::captureCheckpoint( resumed, config, {} );
    ASSERT_EQ( a.arrays.size(), b.arrays.size() );
    for ( std::size_t k = 0; k < a.arrays.size(); ++k )
    {
        const auto& u = a.arrays[k].reals;
        const auto& v = b.arrays[k].reals;
        ASSERT_EQ( u.size(), v.size() ) << a.arrays[k].name;
        for ( std::size_t i = 0; i < u.size(); ++i )
        {
            if ( exact )
                ASSERT_EQ( std::memcmp( &u[i], &v[i], sizeof( double ) ), 0 )
                    << a.arrays[k].name << "[" << i << "]";
            else
                ASSERT_NEAR( u[i], v[i], 1.0e-9 * ( std::abs( u[i] ) + 1.0 ) )
                    << a.arrays[k].name << "[" << i << "]";
        }
        EXPECT_EQ( a.arrays[k].integers, b.arrays[k].integers );
    }

    // A held value changed in the checkpoint is held from there on.
    int held_point = 0; // the first point below 1 m: held
    while ( x0[2 * held_point + 1] > 1.0 )
        ++held_point;
    mpm::Checkpoint changed = checkpoint;
    bool found = false;
    for ( auto& array : changed.arrays )
        if ( array.name == "water/p_w_held_p" )
        {
            array.reals[held_point] = 1234.5;
            found = true;
        }
    ASSERT_TRUE( found );
    mpm::Simulation<TypeParam> edited( config );
    mpm::restoreCheckpoint( edited, config, changed );
    mpm::runStages( edited, config, none, changed.loop );
    EXPECT_EQ( mpm::hostSnapshot( edited ).p_w[held_point], 1234.5 );
}

} // namespace
