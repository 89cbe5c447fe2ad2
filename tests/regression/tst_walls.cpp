// Interior walls and gates (where = "polyline" boundaries) in runs: a dry
// sand block held by a vertical and by an inclined wall, against a control
// without one; the gate of cases/gate_collapse.toml opening between two
// stages; an impermeable wall keeping the water of a sealed side.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( Walls );

//! Which side of a wall a point (x, y) is on: true beyond it.
using Beyond = std::function<bool( double, double )>;

//! Per snapshot: the points beyond the wall line, the largest x and the
//! largest displacement, by stage.
class WallWatcher : public mpm::RunObserver
{
  public:
    explicit WallWatcher( Beyond beyond )
        : _beyond( std::move( beyond ) )
    {
    }
    void onSnapshot( const mpm::RunProgress& progress,
                     const mpm::HostSnapshot& snap ) override
    {
        const std::size_t s = static_cast<std::size_t>( progress.stage_index );
        if ( stages.size() <= s )
            stages.resize( s + 1 );
        Stage& stage = stages[s];
        stage.beyond_now = 0;
        stage.active = 0;
        for ( int p = 0; p < snap.num_points; ++p )
        {
            if ( snap.status[p] != mpm::point_active )
                continue;
            ++stage.active;
            const double x = snap.x[2 * p], y = snap.x[2 * p + 1];
            if ( _beyond( x, y ) )
                ++stage.beyond_now;
            stage.max_x = std::max( stage.max_x, x );
            stage.max_displacement =
                std::max( stage.max_displacement,
                          std::hypot( snap.displacement[2 * p],
                                      snap.displacement[2 * p + 1] ) );
        }
        stage.beyond_ever = std::max( stage.beyond_ever, stage.beyond_now );
        ++stage.snapshots;
    }

    struct Stage
    {
        int snapshots = 0, active = 0;
        int beyond_now = 0;  //!< at the last snapshot
        int beyond_ever = 0; //!< the most at any snapshot
        double max_x = -1.0e300, max_displacement = 0.0;
    };
    std::vector<Stage> stages;

  private:
    Beyond _beyond;
};

mpm::CaseConfig gateCase()
{
    return mpm::readCaseFile( RAINSLIDE_CASES_DIR "/gate_collapse.toml" );
}

//! `config` (by default the gate case) with one dynamic stage, its
//! release stage with `boundaries`, a snapshot every 0.02 s.
mpm::CaseConfig oneDynamicStage( const std::vector<mpm::BoundaryConfig>& b,
                                 mpm::CaseConfig config = gateCase() )
{
    mpm::StageConfig stage = config.stages.at( 1 );
    stage.boundaries = b;
    stage.snapshot_interval_s = 0.02;
    config.stages = { stage };
    return config;
}

template <class ExecSpace>
WallWatcher run( const mpm::CaseConfig& config, const Beyond& beyond )
{
    mpm::Simulation<ExecSpace> sim( config );
    WallWatcher watcher( beyond );
    mpm::runStages( sim, config, watcher );
    return watcher;
}

const Beyond beyond_x1 = []( double x, double ) { return x >= 1.0; };

//---------------------------------------------------------------------------//
// The sand block (1 m x 0.5 m, phi = 30 degrees) against the wall x = 1 m
// under suddenly applied gravity: no point reaches the wall line in 0.6 s
// and the block only settles (elastic settlement 0.33 mm, twice that
// dynamically); without the wall the same block collapses across it.
TYPED_TEST( Walls, vertical_wall_holds_a_block_that_collapses_without_it )
{
    const mpm::CaseConfig held_case = gateCase();
    const auto held = run<TypeParam>(
        oneDynamicStage( held_case.stages.at( 0 ).boundaries ), beyond_x1 );
    ASSERT_EQ( held.stages.size(), 1u );
    EXPECT_GE( held.stages[0].snapshots, 30 );
    EXPECT_EQ( held.stages[0].beyond_ever, 0 );
    EXPECT_LT( held.stages[0].max_x, 1.0 );
    EXPECT_LT( held.stages[0].max_displacement, 2.0e-3 );
    std::printf( "  held: max x %.5f m, max displacement %.3g m\n",
                 held.stages[0].max_x, held.stages[0].max_displacement );

    const auto free = run<TypeParam>(
        oneDynamicStage( held_case.stages.at( 1 ).boundaries ), beyond_x1 );
    EXPECT_GT( free.stages[0].max_x, 1.3 );
    EXPECT_GT( free.stages[0].beyond_now, free.stages[0].active / 20 );
    std::printf( "  no wall: max x %.3f m, %d of %d points beyond x = 1\n",
                 free.stages[0].max_x, free.stages[0].beyond_now,
                 free.stages[0].active );
}

//---------------------------------------------------------------------------//
// An inclined wall from (1, 0) to (1.2, 0.6), 18 degrees off vertical and
// crossing cells: the block filling the space to its left keeps every
// point on its side of the line (the cells it crosses hold their points).
TYPED_TEST( Walls, inclined_wall_keeps_every_point_on_its_side )
{
    mpm::CaseConfig config = gateCase();
    mpm::BoundaryConfig wall = config.boundaries.at( 2 );
    ASSERT_EQ( wall.where, mpm::BoundarySelector::Polyline );
    wall.polyline_m = { { 1.0, 0.0 }, { 1.2, 0.6 } };
    config.bodies[0].polygon_m = {
        { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0 + 0.5 / 3.0, 0.5 }, { 0.0, 0.5 } };
    std::vector<mpm::BoundaryConfig> boundaries =
        config.stages.at( 1 ).boundaries;
    boundaries.push_back( wall );
    config.boundaries = boundaries;
    config.stages.at( 1 ).boundaries = boundaries;
    // Beyond the line: on its right, x >= 1 + y / 3.
    const Beyond beyond = []( double x, double y )
    { return 0.2 * y - 0.6 * ( x - 1.0 ) <= 0.0; };
    const auto held =
        run<TypeParam>( oneDynamicStage( boundaries, config ), beyond );
    EXPECT_GT( held.stages[0].active, 850 ); // the wedge up to the wall
    EXPECT_EQ( held.stages[0].beyond_ever, 0 );
    EXPECT_LT( held.stages[0].max_displacement, 2.0e-3 );
    std::printf( "  inclined: max displacement %.3g m\n",
                 held.stages[0].max_displacement );
}

//---------------------------------------------------------------------------//
// cases/gate_collapse.toml: the block rests against the wall in the
// quasi-static stage, and the release stage (no wall) spreads it past the
// old wall line.
TYPED_TEST( Walls, gate_opens_between_stages )
{
    mpm::CaseConfig config = gateCase();
    ASSERT_EQ( config.stages.size(), 2u );
    config.stages[0].snapshot_interval_s = 0.02;
    const auto watched = run<TypeParam>( config, beyond_x1 );
    ASSERT_EQ( watched.stages.size(), 2u );
    const auto& held = watched.stages[0];
    const auto& released = watched.stages[1];
    EXPECT_EQ( held.beyond_ever, 0 );
    EXPECT_LT( held.max_displacement, 2.0e-3 );
    EXPECT_GT( released.max_x, 1.3 );
    EXPECT_GT( released.beyond_now, released.active / 20 );
    std::printf( "  gate: held max displacement %.3g m; released: max x "
                 "%.3f m, %d of %d points beyond x = 1\n",
                 held.max_displacement, released.max_x, released.beyond_now,
                 released.active );
}

//---------------------------------------------------------------------------//
// In a two-phase scene the empty cells beside a wall or above a fixed
// floor are no soil sliver (fixBaseSlivers): the nodes held are the
// wall's (x = 1 m, 13 nodes) and the floor's (41, one shared), not the
// empty part of the grid. With a roller floor, the wall's and the corner
// the left edge and the floor fix. (Before, the fixed floor seeded
// "slivers" in every empty cell: 353 more nodes fixed, so a two-phase
// block could not run out.)
TYPED_TEST( Walls, two_phase_wall_fixes_no_empty_cell )
{
    for ( const auto floor :
          { mpm::BoundaryCondition::Fixed, mpm::BoundaryCondition::FixY } )
    {
        mpm::CaseConfig config = gateCase();
        config.analysis = mpm::AnalysisType::Saturated;
        mpm::MaterialConfig sand =
            mpm_test::saturatedMaterial( 5.0e6, 0.3, 2650.0, 0.3, 1.0e-10 );
        sand.name = "sand";
        config.materials = { sand };
        for ( auto* list :
              { &config.boundaries, &config.stages[0].boundaries } )
            ( *list )[1].condition = floor;
        for ( auto& stage : config.stages )
            stage.materials = config.materials;
        config.stages.resize( 1 );
        ASSERT_TRUE( config.solver.base_cell_completion );
        mpm::Simulation<TypeParam> sim( config );
        const auto flags = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), sim.grid.flags_i );
        const bool fixed_floor = floor == mpm::BoundaryCondition::Fixed;
        int fully_fixed = 0, fixed_elsewhere = 0;
        for ( int i = 0; i <= config.grid.cells[0]; ++i )
            for ( int j = 0; j <= config.grid.cells[1]; ++j )
                if ( mpm::fullyFixed( flags( i, j ) ) )
                {
                    ++fully_fixed;
                    // A roller floor: the corner (0, 0) is fix_x (left)
                    // and fix_y (floor).
                    const bool floor_node = j == 0 && ( fixed_floor || i == 0 );
                    fixed_elsewhere += i != 20 && !floor_node;
                }
        EXPECT_EQ( fully_fixed, fixed_floor ? 13 + 41 - 1 : 14 );
        EXPECT_EQ( fixed_elsewhere, 0 );
    }
}

//---------------------------------------------------------------------------//
/*
  A saturated layer (2 m x 1 m, K = 1 cm/s, K_w = 1e8 Pa) under a load of
  10 kPa carried by its water (p_w = 10 kPa at the start), split by a wall
  at x = 1 m; only the right edge drains. An impermeable wall seals the
  left half: its water stays and carries the load, while the right half
  drains. With a drained wall (the same solid constraint) the left half
  drains through it.
*/
mpm::CaseConfig splitLayer( const mpm::HydraulicCondition wall_hydraulic )
{
    const double K = 1.0e-2; // m/s
    const double k = K * 1.0e-3 / ( 1000.0 * 9.81 );
    mpm::StageConfig stage;
    stage.name = "drain";
    stage.type = mpm::StageType::Dynamic;
    stage.gravity_m_per_s2 = { 0.0, 0.0 };
    stage.duration_s = 0.2;
    mpm::CaseConfig c = mpm_test::columnCase(
        1.0, 0.1, mpm_test::saturatedMaterial( 1.0e7, 0.0, 2650.0, 0.3, k ),
        stage );
    c.analysis = mpm::AnalysisType::Saturated;
    c.water.bulk_modulus_pa = 1.0e8;
    c.grid.cells = { 20, 10 };
    c.bodies[0].polygon_m = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 }, { 0.0, 1.0 } };
    c.bodies[0].initial_pore_pressure_pa = 1.0e4;
    // columnCase's boundaries: left fix_x, right fix_x, bottom fixed.
    c.boundaries[1].hydraulic = mpm::HydraulicCondition::Drained;
    mpm::BoundaryConfig wall;
    wall.where = mpm::BoundarySelector::Polyline;
    wall.condition = mpm::BoundaryCondition::Fixed;
    wall.hydraulic = wall_hydraulic;
    wall.polyline_m = { { 1.0, 0.0 }, { 1.0, 1.0 } };
    c.boundaries.push_back( wall );
    mpm::PointLoad load;
    load.points.kind = mpm::PointSelection::Kind::Box;
    load.points.box_m = { mpm::Point2{ -1.0, 0.95 }, mpm::Point2{ 3.0, 1.0 } };
    load.traction_pa = { 0.0, -1.0e4 };
    load.length_m = 2.0;
    c.stages[0].boundaries = c.boundaries;
    c.stages[0].loads = { load };
    return c;
}

//! Mean p_w of the points that started left (x < 1) and right of the
//! wall, and their water volume at the reference density, sum of
//! n V (1 + p_w / K_w) (S = 1), m^3 per m.
struct SidePressures
{
    double left = 0.0, right = 0.0;
    double water_left = 0.0, water_right = 0.0;
};

template <class ExecSpace>
SidePressures runSplitLayer( const mpm::HydraulicCondition wall_hydraulic,
                             SidePressures& start )
{
    const mpm::CaseConfig config = splitLayer( wall_hydraulic );
    mpm::Simulation<ExecSpace> sim( config );
    auto x0 = mpm::hostSnapshot( sim ).x;
    auto means = [&]( const mpm::HostSnapshot& snap )
    {
        SidePressures mean;
        int n_left = 0, n_right = 0;
        for ( int p = 0; p < snap.num_points; ++p )
        {
            const bool left = x0[2 * p] < 1.0;
            ( left ? mean.left : mean.right ) += snap.p_w[p];
            ( left ? mean.water_left : mean.water_right ) +=
                snap.n[p] * snap.vol[p] *
                ( 1.0 + snap.p_w[p] / config.water.bulk_modulus_pa );
            ++( left ? n_left : n_right );
        }
        mean.left /= n_left;
        mean.right /= n_right;
        return mean;
    };
    start = means( mpm::hostSnapshot( sim ) );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    return means( mpm::hostSnapshot( sim ) );
}

TYPED_TEST( Walls, impermeable_wall_keeps_the_water_of_the_sealed_side )
{
    SidePressures start;
    const SidePressures sealed =
        runSplitLayer<TypeParam>( mpm::HydraulicCondition::Impermeable, start );
    EXPECT_NEAR( start.left, 1.0e4, 1.0 );
    EXPECT_NEAR( start.right, 1.0e4, 1.0 );
    // The sealed side keeps its water (to the linearised water density's
    // round-off) and carries the load with it: its p_w falls by the few
    // per cent the skeleton takes up as the top points' loads settle the
    // top cells (B = 0.97 with K_w = 1e8 Pa); the right side drains.
    auto change = []( double after, double before )
    { return ( after - before ) / before; };
    EXPECT_LT( std::abs( change( sealed.water_left, start.water_left ) ),
               1.0e-6 );
    EXPECT_LT( change( sealed.water_right, start.water_right ), -1.0e-3 );
    EXPECT_GT( sealed.left, 0.95e4 );
    EXPECT_LT( sealed.right, 0.3e4 );

    const SidePressures drained =
        runSplitLayer<TypeParam>( mpm::HydraulicCondition::Drained, start );
    EXPECT_LT( change( drained.water_left, start.water_left ), -1.0e-3 );
    EXPECT_LT( drained.left, 0.7e4 );
    EXPECT_LT( drained.right, 0.3e4 );
    std::printf( "  mean p_w after 0.2 s, left | right of the wall: "
                 "impermeable %.0f | %.0f Pa, drained %.0f | %.0f Pa\n",
                 sealed.left, sealed.right, drained.left, drained.right );
    std::printf( "  water volume change left | right: impermeable %.3g | "
                 "%.3g, drained %.3g | %.3g (start %.6f | %.6f m^3/m)\n",
                 change( sealed.water_left, start.water_left ),
                 change( sealed.water_right, start.water_right ),
                 change( drained.water_left, start.water_left ),
                 change( drained.water_right, start.water_right ),
                 start.water_left, start.water_right );
}

} // namespace
