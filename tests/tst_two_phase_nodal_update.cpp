// The implicit-drag nodal update of both phases (docs/formulation.md step 2):
// the 2x2 solve, the ties of an impermeable or flux boundary, a fixed solid;
// and the share of a point's seepage the G2P blend keeps over a step.
#include <physics/mpm_two_phase.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using mpm::physics::TwoPhaseNodalUpdate;

constexpr double dt = 1.0e-3;
constexpr double m_s = 2.0, m_w = 0.5;       // kg
constexpr double v_s = 0.1, v_w = -0.3;      // m/s
constexpr double f_m = 4.0, f_w = -1.5;      // N
constexpr double drag = 800.0;               // kg/s
const TwoPhaseNodalUpdate update{ dt, 0.0 }; // no damping

// Residuals of the two momentum equations at the new velocities.
double waterResidual( const TwoPhaseNodalUpdate::Result& r )
{
    return ( m_w / dt + drag ) * r.v_w - drag * r.v_s -
           ( m_w / dt * v_w + f_w );
}
double solidResidual( const TwoPhaseNodalUpdate::Result& r )
{
    return -drag * r.v_w + ( m_s / dt + drag ) * r.v_s -
           ( m_s / dt * v_s + f_m - f_w );
}

TEST( TwoPhaseNodalUpdate, free_node_solves_both_momentum_equations )
{
    const auto r =
        update( m_s, m_w, m_s * v_s, m_w * v_w, f_m, f_w, drag, false, false );
    EXPECT_NEAR( waterResidual( r ), 0.0, 1.0e-9 );
    EXPECT_NEAR( solidResidual( r ), 0.0, 1.0e-9 );
    EXPECT_DOUBLE_EQ( r.dv_s, r.v_s - v_s );
    EXPECT_DOUBLE_EQ( r.dv_w, r.v_w - v_w );
}

// A tie v_w' = v_s' + w: the mixture equation (their sum) holds, the drag
// cancels from it, and the prescribed seepage is carried exactly.
TEST( TwoPhaseNodalUpdate, tied_water_keeps_the_prescribed_seepage )
{
    for ( const double w : { 0.0, -0.05, 0.2 } )
    {
        const auto r = update( m_s, m_w, m_s * v_s, m_w * v_w, f_m, f_w, drag,
                               false, true, w );
        EXPECT_NEAR( r.v_w - r.v_s, w, 1.0e-15 );
        EXPECT_NEAR( waterResidual( r ) + solidResidual( r ), 0.0, 1.0e-9 )
            << "w = " << w;
    }
    // A fixed solid: the water moves at the seepage itself.
    const auto fixed = update( m_s, m_w, m_s * v_s, m_w * v_w, f_m, f_w, drag,
                               true, true, -0.05 );
    EXPECT_EQ( fixed.v_s, 0.0 );
    EXPECT_EQ( fixed.v_w, -0.05 );
}

// The seepage of a prescribed flux: q = n S w with the nodal n S.
TEST( TwoPhaseNodalUpdate, tied_seepage_carries_the_prescribed_flux )
{
    const double rho_w = 1000.0, vol = 0.01, q = 0.04;
    const double nS = m_w / ( rho_w * vol );
    EXPECT_NEAR( nS * mpm::physics::tiedSeepage( q, m_w, m_s, vol, rho_w ), q,
                 1.0e-15 );
    EXPECT_EQ( mpm::physics::tiedSeepage( q, 0.0, m_s, vol, rho_w ), 0.0 );
}

// The drag's decay exp(-dt / tau) of the seepage, tau = f rho_w k k_rel /
// (n S mu), floored at the FLIP share.
TEST( SeepageMemory, decays_at_the_drag_rate_but_not_below_the_flip_share )
{
    const double n = 0.3, k = 4.5e-9, mu = 1.0e-3, rho_w = 1000.0;
    const double tau = rho_w * k / ( n * mu ); // saturated, f = 1: 15 ms
    EXPECT_NEAR( tau, 0.015, 1.0e-12 );
    const auto memory = [&]( const double step, const double S,
                             const double k_rel, const double f,
                             const double flip )
    {
        return mpm::physics::seepageMemory( step, n, S, k, k_rel, mu, rho_w, f,
                                            flip );
    };
    // Small steps: the drag's decay, above the floor.
    EXPECT_NEAR( memory( 1.0e-5, 1.0, 1.0, 1.0, 0.99 ),
                 std::exp( -1.0e-5 / tau ), 1.0e-15 );
    EXPECT_NEAR( memory( 1.0e-5, 1.0, 1.0, 4.0, 0.99 ),
                 std::exp( -1.0e-5 / ( 4.0 * tau ) ), 1.0e-15 );
    EXPECT_NEAR( memory( 1.0e-5, 0.5, 0.25, 1.0, 0.99 ),
                 std::exp( -1.0e-5 * 0.5 / ( 0.25 * tau ) ), 1.0e-15 );
    // A 3e-4 s step decays it to 0.980: the FLIP share 0.99 is kept.
    EXPECT_EQ( memory( 3.0e-4, 1.0, 1.0, 1.0, 0.99 ), 0.99 );
    // Near-dry (k_rel 1e-10) and impermeable points keep the FLIP share.
    EXPECT_EQ( memory( 1.0e-5, 0.23, 1.0e-10, 1.0, 0.995 ), 0.995 );
    EXPECT_EQ( memory( 1.0e-5, 1.0, 0.0, 1.0, 0.995 ), 0.995 );
}

} // namespace
