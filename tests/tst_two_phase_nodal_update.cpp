// The implicit-drag nodal update of both phases (formulation.md step 2):
// the 2x2 solve, the ties of an impermeable or flux boundary, a fixed solid.
#include <physics/mpm_two_phase.hpp>

#include <gtest/gtest.h>

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

} // namespace
