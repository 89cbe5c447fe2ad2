#include <physics/mpm_pressure_mobility.hpp>
#include <physics/mpm_two_phase.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
//---------------------------------------------------------------------------//
// The mobilities are step 2's drag solve on a pressure-gradient force: a
// node of unit volume with the point's masses and drag, loaded by the
// forces of dp (water: n S V grad dp, mixture: S V grad dp, both against the
// gradient), moves its phases by -dt Lambda grad dp.
TEST( PressureMobility, equals_the_nodal_drag_solve_on_a_pressure_force )
{
    std::mt19937 rng( 7 );
    std::uniform_real_distribution<double> unit( 0.0, 1.0 );
    const double rho_w = 1000.0, mu = 1.0e-3;
    double worst = 0.0;
    for ( int trial = 0; trial < 2000; ++trial )
    {
        const double n = 0.1 + 0.5 * unit( rng );
        const double S = 0.05 + 0.95 * unit( rng );
        const double rho_s = ( 1.0 - n ) * ( 1500.0 + 1500.0 * unit( rng ) );
        const double k = std::pow( 10.0, -15.0 + 8.0 * unit( rng ) );
        const double k_rel = std::pow( 10.0, -4.0 * unit( rng ) );
        const double f = std::pow( 10.0, 5.0 * unit( rng ) );
        const double dt = std::pow( 10.0, -6.0 + 5.0 * unit( rng ) );
        const double grad = 1.0e3 * ( unit( rng ) - 0.5 );
        const auto m = mpm::physics::pressureMobility( n, S, rho_s, rho_w, k,
                                                       k_rel, mu, f, dt );
        const double nS = n * S, vol = 1.0;
        const double drag = nS * nS * mu * vol / ( k * k_rel );
        const mpm::physics::TwoPhaseNodalUpdate update{ dt, 0.0, f };
        // The water force per unit water fraction times the nodal n S.
        const auto r =
            update( rho_s * vol, nS * rho_w * vol, 0.0, 0.0, -S * vol * grad,
                    nS * ( -vol * grad ), drag, false, false );
        const double scale = std::abs( dt * grad ) / rho_w;
        worst =
            std::max( { worst, std::abs( r.v_w + dt * m.water * grad ) / scale,
                        std::abs( r.v_s + dt * m.solid * grad ) / scale } );
        EXPECT_NEAR( m.mixture, nS * m.water + ( 1.0 - n ) * S * m.solid,
                     1.0e-14 * m.mixture );
    }
    // Achieved: 2e-16 of dt |grad| / rho_w.
    EXPECT_LT( worst, 1.0e-12 );
}

// The limits: drag-free phases accelerate on their own densities; locked
// water (k_rel = 0) moves with the solid as one mixture; no water, the
// solid alone.
TEST( PressureMobility, drag_free_locked_and_dry_limits )
{
    const double n = 0.3, S = 0.8, rho_s = 0.7 * 2650.0, rho_w = 1000.0;
    const double f = 2.0;
    const auto free = mpm::physics::pressureMobility( n, S, rho_s, rho_w, 1.0,
                                                      1.0, 1.0e-30, f, 1.0e-3 );
    EXPECT_NEAR( free.water, 1.0 / ( f * rho_w ), 1.0e-12 / rho_w );
    EXPECT_NEAR( free.solid, ( 1.0 - n ) * S / ( f * rho_s ), 1.0e-12 / rho_w );
    const auto locked = mpm::physics::pressureMobility(
        n, S, rho_s, rho_w, 1.0e-12, 0.0, 1.0e-3, f, 1.0e-3 );
    const double mixture = S / ( f * ( n * S * rho_w + rho_s ) );
    EXPECT_DOUBLE_EQ( locked.water, mixture );
    EXPECT_DOUBLE_EQ( locked.solid, mixture );
    EXPECT_DOUBLE_EQ( locked.mixture, S * mixture );
    const auto dry = mpm::physics::pressureMobility(
        n, 0.0, rho_s, rho_w, 1.0e-12, 1.0, 1.0e-3, f, 1.0e-3 );
    EXPECT_EQ( dry.water, 0.0 );
    EXPECT_EQ( dry.mixture, 0.0 );
}

// Eq. 8's storage: the retention slope and the water's compression.
TEST( PressureMobility, storage_is_retention_slope_plus_compression )
{
    EXPECT_DOUBLE_EQ( mpm::physics::waterStorage( 0.3, 0.5, 2.0e-5, 2.0e9 ),
                      0.3 * 2.0e-5 + 0.3 * 0.5 / 2.0e9 );
}

} // namespace
