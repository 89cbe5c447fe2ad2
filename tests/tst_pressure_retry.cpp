// The semi-implicit step takes a step whose pressure iteration fails again
// in two halves (Simulation::advance), down to dt / 2^6, and only then
// accepts the last iterate.
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/mpm_simulation.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
MPM_TEST_BACKEND_SUITE( PressureRetry );

//! An unsaturated column of the paper's soil at 20 kPa suction under
//! sudden gravity, semi-implicit, the Picard iteration asked for a water
//! residual of `picard_tolerance` |b|.
mpm::CaseConfig column( const double picard_tolerance )
{
    auto c = mpm_test::paperSoilColumn( 1.0, 1.0, -9.81 );
    c.bodies[0].initial_pore_pressure_pa = -2.0e4;
    c.solver.scheme = mpm::TwoPhaseScheme::SemiImplicit;
    c.solver.pressure_picard_tolerance = picard_tolerance;
    return c;
}

//---------------------------------------------------------------------------//
// A residual of 1e-17 |b| is below round-off: every attempt fails, so one
// step becomes 2^6 steps of dt / 2^6 after 1 + 2 + ... + 32 = 63 failed
// attempts, and the simulated time is still dt.
TYPED_TEST( PressureRetry, failed_iteration_is_taken_again_in_halves )
{
    mpm::Simulation<TypeParam> sim( column( 1.0e-17 ) );
    const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };
    const double dt = 0.5 * sim.waveSpeedLimit().dt_limit;
    const double stored_before = sim.waterContent().active;
    sim.advance( dt, settings );
    const mpm::PressureSolveStats* stats = sim.pressureSolveStats();
    ASSERT_NE( stats, nullptr );
    // The step's water ledger holds all its parts, not the last half only
    // (3e-6 of the change achieved).
    const mpm::physics::WaterStepVolumes& water = sim.stepWater();
    const double stored_change = sim.waterContent().active - stored_before;
    const double booked =
        water.point_inflow - water.runoff + water.prescribed + water.flow_in;
    std::printf( "[ retry ] stored change %.6e m^3/m, booked %.6e\n",
                 stored_change, booked );
    EXPECT_NEAR( booked, stored_change, 1.0e-5 * std::fabs( stored_change ) );
    const int halves = 1 << mpm::Simulation<TypeParam>::max_pressure_halvings;
    EXPECT_EQ( stats->retried_steps, halves - 1 );
    EXPECT_EQ( stats->picard_unconverged, halves );
    EXPECT_EQ( sim.step, halves );
    EXPECT_NEAR( sim.time, dt, 1.0e-12 * dt );
    sim.checkStability( dt / halves, sim.waveSpeedLimit() );
}

// A reachable tolerance: the same step is one step, never retried.
TYPED_TEST( PressureRetry, converged_iteration_is_one_step )
{
    mpm::Simulation<TypeParam> sim( column( 1.0e-6 ) );
    const mpm::StepSettings settings{ 0.0, -9.81, 0.0 };
    const double dt = 0.5 * sim.waveSpeedLimit().dt_limit;
    sim.advance( dt, settings );
    const mpm::PressureSolveStats* stats = sim.pressureSolveStats();
    ASSERT_NE( stats, nullptr );
    EXPECT_EQ( stats->retried_steps, 0 );
    EXPECT_EQ( stats->picard_unconverged, 0 );
    EXPECT_EQ( sim.step, 1 );
    EXPECT_DOUBLE_EQ( sim.time, dt );
}

} // namespace
