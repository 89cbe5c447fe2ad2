// The diagnostics a step leaves behind (CFL limit, kinetic energy,
// stability) and its stored retention state are exactly what the separate
// reductions and a full retention evaluation give.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( StepDiagnostics );

//! An unsaturated elastic column at 20 kPa suction (van Genuchten) under
//! sudden gravity, with B-bar if `bbar`.
mpm::CaseConfig unsaturatedColumn( const bool bbar )
{
    mpm::StageConfig stage;
    stage.name = "gravity";
    stage.type = mpm::StageType::Dynamic;
    stage.gravity_m_per_s2 = { 0.0, -9.81 };
    stage.duration_s = 1.0;
    const auto soil = mpm_test::withPaperRetention(
        mpm_test::saturatedMaterial( 1.0e7, 0.3, 2700.0, 0.3, 4.5e-9 ) );
    auto c = mpm_test::columnCase( 1.0, 0.125, soil, stage );
    c.analysis = mpm::AnalysisType::Unsaturated;
    c.bodies[0].initial_pore_pressure_pa = -2.0e4;
    c.solver.bbar = bbar;
    return c;
}

//---------------------------------------------------------------------------//
TYPED_TEST( StepDiagnostics, cached_values_equal_fresh_reductions )
{
    for ( const bool bbar : { false, true } )
    {
        const auto config = unsaturatedColumn( bbar );
        mpm::Simulation<TypeParam> sim( config );
        const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };
        for ( int k = 0; k < 30; ++k )
        {
            const mpm::WaveSpeedLimit limit = sim.waveSpeedLimit();
            const double dt = 0.5 * limit.dt_limit;
            sim.advance( dt, settings );
            sim.checkStability( dt, limit );
            const mpm::WaveSpeedLimit cached = sim.waveSpeedLimit();
            const double energy = sim.kineticEnergy();
            sim.stateChanged(); // forces the separate reductions
            const mpm::WaveSpeedLimit fresh = sim.waveSpeedLimit();
            EXPECT_EQ( cached.dt_limit, fresh.dt_limit ) << "step " << k;
            EXPECT_EQ( cached.max_wave_speed, fresh.max_wave_speed );
            // Serial sums in the same order; OpenMP may join differently.
            EXPECT_NEAR( energy, sim.kineticEnergy(),
                         1e-13 * sim.kineticEnergy() );
        }
        EXPECT_GT( sim.kineticEnergy(), 0.0 );
    }
}

//---------------------------------------------------------------------------//
// Reusing the stored retention state (and skipping held points) changes
// nothing: the run equals one that forgets it every step.
TYPED_TEST( StepDiagnostics, stored_retention_state_changes_nothing )
{
    auto config = unsaturatedColumn( false );
    // Hold p_w on the top half, as a rainfall boundary holds its points.
    mpm::PorePressureCondition held;
    held.points.kind = mpm::PointSelection::Kind::Box;
    held.points.box_m = { mpm::Point2{ -1.0, 0.5 }, mpm::Point2{ 1.0, 2.0 } };
    held.pressure_pa = -1.0e4;
    config.stages[0].pore_pressures = { held };
    const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };

    mpm::Simulation<TypeParam> kept( config );
    mpm::Simulation<TypeParam> forgot( config );
    const double dt = 0.5 * kept.waveSpeedLimit().dt_limit;
    for ( int k = 0; k < 40; ++k )
    {
        kept.advance( dt, settings );
        forgot.advance( dt, settings );
        forgot.stateChanged();
    }
    const auto a = mpm::hostSnapshot( kept );
    const auto b = mpm::hostSnapshot( forgot );
    EXPECT_EQ( a.p_w, b.p_w );
    EXPECT_EQ( a.S, b.S );
    EXPECT_EQ( a.k_rel, b.k_rel );
    EXPECT_EQ( a.sigma, b.sigma );
    EXPECT_EQ( a.x, b.x );
}

//---------------------------------------------------------------------------//
// A NaN strain or plastic shear strain stops the run naming the quantity
// (issue 12: the soundness check covered only x, stress, volume, p_w, v_w
// and the speed).
TYPED_TEST( StepDiagnostics, non_finite_strain_is_unsound )
{
    const auto config = unsaturatedColumn( false );
    const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for ( const bool plastic : { false, true } )
    {
        mpm::Simulation<TypeParam> sim( config );
        const double dt = 0.5 * sim.waveSpeedLimit().dt_limit;
        sim.advance( dt, settings );
        if ( plastic )
        {
            auto h = Kokkos::create_mirror_view_and_copy(
                Kokkos::HostSpace(), sim.particles.eps_p_bar_p );
            h( 3 ) = nan;
            Kokkos::deep_copy( sim.particles.eps_p_bar_p, h );
        }
        else
        {
            auto h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                          sim.particles.eps_p );
            h( 3, 2 ) = nan;
            Kokkos::deep_copy( sim.particles.eps_p, h );
        }
        sim.stateChanged();
        EXPECT_EQ( mpm::findUnstablePoint( TypeParam(), sim.particles,
                                           sim.water_particles, 1.0e30 ),
                   3 );
        try
        {
            sim.checkStability( dt, sim.waveSpeedLimit() );
            ADD_FAILURE() << "a NaN strain passed the stability check";
        }
        catch ( const mpm::SimulationError& e )
        {
            const std::string expected =
                plastic ? "plastic shear strain (eps_p_bar) is not finite"
                        : "strain is not finite";
            EXPECT_NE( std::string( e.what() ).find( expected ),
                       std::string::npos )
                << e.what();
        }
    }
}

//---------------------------------------------------------------------------//
// The size of a mechanism (strength-reduction trials): the initial area of
// the active points displaced more than a threshold.
TYPED_TEST( StepDiagnostics, moved_area_sums_the_displaced_points )
{
    mpm::Simulation<TypeParam> sim( unsaturatedColumn( false ) );
    auto x = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                  sim.particles.x_p );
    auto status = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                       sim.particles.status_p );
    const auto vol0 = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), sim.particles.vol0_p );
    ASSERT_GE( x.extent( 0 ), 6u );
    // Points 0-2 move 2 mm along x, 3 moves 2 mm along y and is removed,
    // 4 moves 0.5 mm.
    for ( int p = 0; p < 3; ++p )
        x( p, 0 ) += 0.002;
    x( 3, 1 ) -= 0.002;
    status( 3 ) = mpm::point_removed;
    x( 4, 0 ) += 0.0005;
    Kokkos::deep_copy( sim.particles.x_p, x );
    Kokkos::deep_copy( sim.particles.status_p, status );
    sim.stateChanged();
    const double area = vol0( 0 ) + vol0( 1 ) + vol0( 2 );
    EXPECT_NEAR( sim.movedArea( 0.001 ), area, 1e-14 * area );
    EXPECT_NEAR( sim.movedArea( 0.0001 ), area + vol0( 4 ), 1e-14 * area );
    EXPECT_EQ( sim.movedArea( 0.003 ), 0.0 );
    EXPECT_NEAR( sim.maxDisplacement(), 0.002, 1e-12 );
}

} // namespace
