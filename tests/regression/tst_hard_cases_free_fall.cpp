// Hard cases (HardCases) of blocks without boundary conditions: free fall
// across cells, points leaving the grid, a non-finite state.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_hard_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace
{
using mpm_test::hard_cases::HardCases;
TYPED_TEST_SUITE( HardCases, mpm_test::Backends, mpm_test::BackendName );

using namespace mpm_test::hard_cases;

//---------------------------------------------------------------------------//
// The slope soil of the paper (Table 2): E = 10 MPa, nu = 0.33,
using mpm_test::paperSoil;

//! A saturated block `polygon_m` of the paper's soil without its retention
//! law on `cells` cells of 0.25 m, one `stage`; points leaving the grid
//! are removed if `remove`.
mpm::CaseConfig saturatedBlock( const std::string& name,
                                const std::array<int, 2>& cells,
                                const std::vector<mpm::Point2>& polygon_m,
                                mpm::StageConfig stage, const bool remove )
{
    mpm::CaseConfig config;
    config.file = "<test>";
    config.name = name;
    config.analysis = mpm::AnalysisType::Saturated;
    config.grid.origin_m = { 0.0, 0.0 };
    config.grid.cell_size_m = 0.25;
    config.grid.cells = cells;
    auto soil = paperSoil();
    soil.retention = mpm::RetentionConfig{};
    config.materials = { soil };
    mpm::BodyConfig block;
    block.material = soil.name;
    block.polygon_m = polygon_m;
    config.bodies = { block };
    stage.materials = config.materials;
    config.stages = { stage };
    config.solver.remove_points_leaving_grid = remove;
    return config;
}

//! The message of the SimulationError that stops the run of `config`
//! ("" if it completes).
template <class ExecSpace>
std::string stopMessage( mpm::Simulation<ExecSpace>& sim,
                         const mpm::CaseConfig& config )
{
    mpm::RunObserver observer;
    try
    {
        mpm::runStages( sim, config, observer );
    }
    catch ( const mpm::SimulationError& error )
    {
        return error.what();
    }
    return "";
}

//---------------------------------------------------------------------------//
/*!
  5. Points crossing cells: a 1 m x 1 m block (2 x 2 points in 0.25 m
  cells) falls freely under a tilted gravity g = (3, -9) m/s^2 through a
  grid without boundary conditions, crossing ~6 cells in x and ~18 in y in
  1 s; saturated (p_w = 0) and dry. Free fall is exact for the continuum:
  no stress, no pore pressure, no relative water motion. Checks: the total
  solid mass is conserved exactly (no point is lost), the water mass to
  1e-12, the centre of mass follows x0 + g t^2 / 2 within 1 % of the
  distance fallen (t >= 0.25 s; the update x += dt v^(n+1) gives
  g t (t + dt) / 2, a relative error dt / t: 0.6 % for the dry block,
  dt = 1.5 ms, at 0.25 s), the momentum is M g t and the kinetic
  energy 1/2 M (g t)^2 within 1 % (the free-fall energy is also the
  physical upper bound), and the block does not deform (point speeds
  within 1e-6 of the mean).
*/
TYPED_TEST( HardCases, falling_block_follows_free_fall )
{
    const double h = 0.25, g_x = 3.0, g_y = -9.0;
    for ( const auto analysis :
          { mpm::AnalysisType::Saturated, mpm::AnalysisType::Dry } )
    {
        const bool two_phase = analysis != mpm::AnalysisType::Dry;
        mpm::CaseConfig config;
        config.file = "<test>";
        config.name = "falling_block";
        config.analysis = analysis;
        config.grid.origin_m = { 0.0, 0.0 };
        config.grid.cell_size_m = h;
        config.grid.cells = { 16, 32 }; // 4 m x 8 m
        auto soil = two_phase
                        ? paperSoil()
                        : mpm_test::elasticMaterial( 1.0e7, 0.33, 2100.0 );
        if ( two_phase )
            soil.retention = mpm::RetentionConfig{};
        config.materials = { soil };
        mpm::BodyConfig block;
        block.material = soil.name;
        block.polygon_m = {
            { 0.5, 6.0 }, { 1.5, 6.0 }, { 1.5, 7.0 }, { 0.5, 7.0 } };
        config.bodies = { block };
        mpm::StageConfig stage;
        stage.name = "fall";
        stage.type = mpm::StageType::Dynamic;
        stage.gravity_m_per_s2 = { g_x, g_y };
        stage.duration_s = 1.0;
        stage.snapshot_times_s = { 0.25, 0.5, 0.75 };
        stage.materials = config.materials;
        config.stages = { stage };

        mpm::Simulation<TypeParam> sim( config );
        const auto initial = mpm::hostSnapshot( sim );
        double m_s0 = 0.0, x_c0 = 0.0, y_c0 = 0.0;
        for ( int p = 0; p < initial.num_points; ++p )
        {
            m_s0 += initial.mass[p];
            x_c0 += initial.mass[p] * initial.x[2 * p];
            y_c0 += initial.mass[p] * initial.x[2 * p + 1];
        }
        x_c0 /= m_s0;
        y_c0 /= m_s0;
        const double m_0 = mixtureMass( initial );
        Recorder recorder;
        ASSERT_NO_THROW( mpm::runStages( sim, config, recorder ) );
        EXPECT_EQ( sim.num_removed, 0 );
        const auto& snaps = recorder.snapshots[0];
        ASSERT_EQ( snaps.size(), 4u );
        double worst = 0.0;
        for ( const auto& [t, snap] : snaps )
        {
            EXPECT_EQ( countNonFinite( snap ), 0 );
            double m_s = 0.0, x_c = 0.0, y_c = 0.0, p_x = 0.0, p_y = 0.0;
            for ( int p = 0; p < snap.num_points; ++p )
            {
                m_s += snap.mass[p];
                x_c += snap.mass[p] * snap.x[2 * p];
                y_c += snap.mass[p] * snap.x[2 * p + 1];
                p_x += snap.mass[p] * snap.v[2 * p];
                p_y += snap.mass[p] * snap.v[2 * p + 1];
            }
            x_c /= m_s;
            y_c /= m_s;
            EXPECT_EQ( m_s, m_s0 ) << "solid mass, t = " << t;
            EXPECT_NEAR( mixtureMass( snap ), m_0, 1.0e-12 * m_0 )
                << "mixture mass, t = " << t;
            const double fall = 0.5 * std::hypot( g_x, g_y ) * t * t;
            const double error = std::hypot( x_c - x_c0 - 0.5 * g_x * t * t,
                                             y_c - y_c0 - 0.5 * g_y * t * t ) /
                                 fall;
            worst = std::max( worst, error );
            EXPECT_LT( error, 0.01 ) << "centre of mass, t = " << t;
            EXPECT_NEAR( p_x, m_s * g_x * t, 0.01 * m_s * std::abs( g_x ) * t );
            EXPECT_NEAR( p_y, m_s * g_y * t, 0.01 * m_s * std::abs( g_y ) * t );
            double spread = 0.0;
            for ( int p = 0; p < snap.num_points; ++p )
                spread =
                    std::max( { spread, std::abs( snap.v[2 * p] - p_x / m_s ),
                                std::abs( snap.v[2 * p + 1] - p_y / m_s ) } );
            EXPECT_LT( spread, 1.0e-6 ) << "t = " << t;
            if ( two_phase )
                for ( int p = 0; p < snap.num_points; ++p )
                {
                    ASSERT_LT( std::abs( snap.p_w[p] ), 1.0 ) << "t = " << t;
                    ASSERT_LT(
                        std::abs( snap.v_w[2 * p + 1] - snap.v[2 * p + 1] ),
                        1.0e-6 )
                        << "t = " << t;
                }
        }
        const double v_end = std::hypot( g_x, g_y ) * 1.0;
        const double ke_free = 0.5 * m_s0 * v_end * v_end;
        std::printf( "falling block (%s): worst centre-of-mass error %.2e of "
                     "the fall, KE max %.6g J (free fall %.6g J)\n",
                     two_phase ? "saturated" : "dry", worst, recorder.ke_max[0],
                     ke_free );
        EXPECT_NEAR( recorder.ke_max[0], ke_free, 0.01 * ke_free );
    }
}

//---------------------------------------------------------------------------//
/*!
  7. A point leaving the grid in a two-phase scene: a saturated block
  falls out through the bottom of a grid without boundary conditions.
  With remove_points_leaving_grid = false the run stops with a
  SimulationError naming the point, its position (below the grid) and
  'left the grid'. With true the run completes, the points that left are
  counted, and the remaining points still fall freely (v_y = g t within
  1 %); when every point has left, the run still completes.
*/
TYPED_TEST( HardCases, points_leaving_the_grid )
{
    const double h = 0.25, g = 9.81;
    auto makeCase = [&]( const bool remove, const double duration )
    {
        return saturatedBlock(
            "leaving", { 8, 12 }, // 2 m x 3 m
            { { 0.5, 1.5 }, { 1.5, 1.5 }, { 1.5, 2.5 }, { 0.5, 2.5 } },
            mpm_test::stageConfig( "fall", mpm::StageType::Dynamic, duration,
                                   -g ),
            remove );
    };

    { // stop with a diagnosis
        const auto config = makeCase( false, 1.0 );
        mpm::Simulation<TypeParam> sim( config );
        const std::string message = stopMessage( sim, config );
        std::printf( "leaving the grid: \"%s\"\n", message.c_str() );
        ASSERT_FALSE( message.empty() ) << "no SimulationError";
        EXPECT_NE( message.find( "material point " ), std::string::npos );
        EXPECT_NE( message.find( "left the grid" ), std::string::npos );
        EXPECT_NE( message.find( "pore pressure" ), std::string::npos );
        const auto at = message.find( "position (" );
        ASSERT_NE( at, std::string::npos );
        double x = 0.0, y = 0.0;
        ASSERT_EQ(
            std::sscanf( message.c_str() + at, "position (%lf, %lf)", &x, &y ),
            2 );
        EXPECT_LT( y, 0.0 ); // below the grid
        int id = -1;
        ASSERT_EQ(
            std::sscanf( message.c_str() + message.find( "material point " ),
                         "material point %d", &id ),
            1 );
        const auto snap = mpm::hostSnapshot( sim );
        ASSERT_GE( id, 0 );
        ASSERT_LT( id, snap.num_points );
        EXPECT_NEAR( snap.x[2 * id + 1], y, 1.0e-5 * std::abs( y ) );
        // Its row started at y0 = 1.5 m + (1/2 - 1/sqrt(12)) h and fell
        // freely: it left at t = sqrt(2 y0 / g).
        const double y0 = 1.5 + ( 0.5 - 0.5 / std::sqrt( 3.0 ) ) * h;
        EXPECT_NEAR( snap.x[2 * id + 1] - snap.displacement[2 * id + 1], y0,
                     1.0e-12 );
        EXPECT_NEAR( sim.time, std::sqrt( 2.0 * y0 / g ), 0.01 );
    }

    { // remove and go on: half of the block has left at 0.6 s
        const double t_end = 0.6;
        const auto config = makeCase( true, t_end );
        mpm::Simulation<TypeParam> sim( config );
        double m_s = 0.0;
        for ( const double m : mpm::hostSnapshot( sim ).mass )
            m_s += m;
        Recorder recorder;
        ASSERT_NO_THROW( mpm::runStages( sim, config, recorder ) );
        const auto snap = mpm::hostSnapshot( sim );
        // Free fall bounds the kinetic energy: 1/2 M (g t)^2.
        const double ke_free = 0.5 * m_s * ( g * t_end ) * ( g * t_end );
        std::printf( "removed %d of %d points, KE max %.4g J (free fall of "
                     "the whole block %.4g J)\n",
                     sim.num_removed, snap.num_points, recorder.ke_max[0],
                     ke_free );
        EXPECT_LE( recorder.ke_max[0], ke_free * ( 1.0 + 1.0e-9 ) );
        EXPECT_GT( sim.num_removed, 0 );
        EXPECT_LT( sim.num_removed, snap.num_points );
        EXPECT_EQ( sim.numActivePoints() + sim.num_removed, snap.num_points );
        int active = 0;
        for ( int p = 0; p < snap.num_points; ++p )
        {
            if ( snap.status[p] != mpm::point_active )
                continue;
            ++active;
            EXPECT_TRUE( std::isfinite( snap.p_w[p] ) );
            EXPECT_GE( snap.x[2 * p + 1], 0.0 );
            EXPECT_NEAR( snap.v[2 * p + 1], -g * t_end, 0.01 * g * t_end );
        }
        EXPECT_EQ( active, sim.numActivePoints() );
    }

    { // every point leaves
        const auto config = makeCase( true, 1.0 );
        mpm::Simulation<TypeParam> sim( config );
        mpm::RunObserver observer;
        ASSERT_NO_THROW( mpm::runStages( sim, config, observer ) );
        EXPECT_EQ( sim.numActivePoints(), 0 );
    }
}

//---------------------------------------------------------------------------//
/*!
  9. A non-finite state is an instability, never a point leaving the grid.
  A saturated block at rest inside the grid (no gravity) whose point 0 is
  given p_w = NaN: the first step spreads NaN to the positions of the
  points around it. With and without remove_points_leaving_grid, the run
  must stop with a SimulationError that calls the point unstable (a
  quantity not finite), must not call it 'left the grid', and must not
  remove (hide) any point.
*/
TYPED_TEST( HardCases, non_finite_state_is_not_a_point_leaving_the_grid )
{
    for ( const bool remove : { false, true } )
    {
        const mpm::CaseConfig config = saturatedBlock(
            "nan", { 8, 8 },
            { { 0.5, 0.5 }, { 1.5, 0.5 }, { 1.5, 1.5 }, { 0.5, 1.5 } },
            mpm_test::stageConfig( "rest", mpm::StageType::Dynamic, 0.01, 0.0 ),
            remove );

        mpm::Simulation<TypeParam> sim( config );
        auto p_w = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), sim.water_particles.p_w_p );
        p_w( 0 ) = std::nan( "" );
        Kokkos::deep_copy( sim.water_particles.p_w_p, p_w );
        const std::string message = stopMessage( sim, config );
        std::printf( "NaN state (remove_points_leaving_grid = %d): %d points "
                     "removed, \"%s\"\n",
                     remove, sim.num_removed,
                     message.substr( 0, message.find( '\n' ) ).c_str() );
        EXPECT_FALSE( message.empty() ) << "the run did not stop";
        EXPECT_NE( message.find( "is unstable" ), std::string::npos )
            << message;
        EXPECT_NE( message.find( "finite" ), std::string::npos ) << message;
        EXPECT_EQ( message.find( "left the grid" ), std::string::npos )
            << message;
        EXPECT_EQ( sim.num_removed, 0 );
    }
}

} // namespace
