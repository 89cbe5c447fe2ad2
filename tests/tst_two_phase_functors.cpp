// The two-phase physics functors of the step, on the host against values
// computed by hand: Bishop's total stress and a point's share of the P2G
// sums (step 1), the nodal water state, drag and remapped water velocity
// (steps 2, 4), the wave speeds of the time step (step 10), and the water
// volume rate, porosity, inflow source and pressure rules of the point
// update (steps 6, 7).
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_kinematics.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_point_water.hpp>
#include <physics/mpm_two_phase_scatter.hpp>
#include <physics/mpm_wave_speeds.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
namespace ph = mpm::physics;

//---------------------------------------------------------------------------//
// Eq. 11: sigma = sigma' - S p_w m. Suction (p_w < 0) makes the total
// stress less compressive than the effective one; no shear part.
TEST( TwoPhaseScatter, bishop_total_stress )
{
    const double sigma_eff[3] = { -10.0e3, -20.0e3, 3.0e3 };
    double sigma[3];
    ph::bishopTotalStress( sigma_eff, 0.5, -40.0e3, sigma );
    EXPECT_DOUBLE_EQ( sigma[0], 10.0e3 );
    EXPECT_DOUBLE_EQ( sigma[1], 0.0 );
    EXPECT_DOUBLE_EQ( sigma[2], 3.0e3 );
    // Saturated, p_w = 5 kPa: the water carries 5 kPa of compression.
    ph::bishopTotalStress( sigma_eff, 1.0, 5.0e3, sigma );
    EXPECT_DOUBLE_EQ( sigma[0], -15.0e3 );
    EXPECT_DOUBLE_EQ( sigma[1], -25.0e3 );
}

// A point of V = 0.25 m^3, n = 0.4, S = 0.5, p_w = -40 kPa, m_s = 600 kg,
// k k_rel = 1e-12 m^2, under g = (0, -10) and a load (100, 0) N.
ph::TwoPhasePoint examplePoint()
{
    const double sigma_eff[3] = { -10.0e3, -20.0e3, 3.0e3 };
    const double v_s[2] = { 0.1, -0.2 }, v_w[2] = { 0.3, 0.4 };
    const double g[2] = { 0.0, -10.0 }, load[2] = { 100.0, 0.0 };
    return ph::twoPhasePoint( 0.25, 0.4, 0.5, -40.0e3, 600.0, sigma_eff,
                              1.0e-12, v_s, v_w, g, load, 1000.0 );
}

TEST( TwoPhaseScatter, point_quantities )
{
    const auto point = examplePoint();
    EXPECT_DOUBLE_EQ( point.m_w, 50.0 ); // 0.4 x 0.5 x 1000 x 0.25
    EXPECT_DOUBLE_EQ( point.permeability_volume, 0.25e-12 );
    EXPECT_DOUBLE_EQ( point.sigma[0], 10.0e3 );
    EXPECT_DOUBLE_EQ( point.f_m[0], 100.0 );   // the load
    EXPECT_DOUBLE_EQ( point.f_m[1], -6500.0 ); // (600 + 50) x -10
    EXPECT_DOUBLE_EQ( point.water_density * point.vol * point.g[1],
                      -2500.0 ); // the water's weight, 1000 x 0.25 x -10
}

TEST( TwoPhaseScatter, node_share_by_hand )
{
    const auto point = examplePoint();
    const double grad_N[2] = { 0.5, -0.25 };
    const auto share = ph::twoPhaseNodeShare( point, 0.25, grad_N );
    EXPECT_DOUBLE_EQ( share.m_s, 150.0 );
    EXPECT_DOUBLE_EQ( share.m_w, 12.5 );
    EXPECT_DOUBLE_EQ( share.vol, 0.0625 );
    EXPECT_DOUBLE_EQ( share.mv_s[1], 0.25 * 600.0 * -0.2 );
    EXPECT_DOUBLE_EQ( share.mv_w[0], 0.25 * 50.0 * 0.3 );
    // sigma . grad N = (10e3 x 0.5 + 3e3 x -0.25, 3e3 x 0.5 + 0 x -0.25)
    //                = (4250, 1500) Pa/m.
    EXPECT_DOUBLE_EQ( share.f_m[0], 0.25 * 100.0 - 0.25 * 4250.0 );
    EXPECT_DOUBLE_EQ( share.f_m[1], 0.25 * -6500.0 - 0.25 * 1500.0 );
    // rho_w V g N + p_w V grad N.
    EXPECT_DOUBLE_EQ( share.f_w[0], -40.0e3 * 0.25 * 0.5 );
    EXPECT_DOUBLE_EQ( share.f_w[1], 0.25 * -2500.0 + -40.0e3 * 0.25 * -0.25 );
}

// Over the 4 nodes of the point's cell (sum N = 1, sum grad N = 0) the
// shares add up to the point: mass, momentum, weight and loads; the stress
// and pressure terms cancel.
TEST( TwoPhaseScatter, node_shares_add_up_to_the_point )
{
    const auto point = examplePoint();
    ph::GridGeometry grid;
    grid.h = 0.5;
    grid.nx = grid.ny = 4;
    int ci, cj;
    double w[4], dwdx[4], dwdy[4];
    grid.weights( 0.61, 1.37, ci, cj, w, dwdx, dwdy );
    ph::TwoPhaseNodeShare total{};
    for ( int k = 0; k < 4; ++k )
    {
        const double grad_N[2] = { dwdx[k], dwdy[k] };
        const auto share = ph::twoPhaseNodeShare( point, w[k], grad_N );
        total.m_s += share.m_s;
        total.m_w += share.m_w;
        for ( int d = 0; d < 2; ++d )
        {
            total.mv_w[d] += share.mv_w[d];
            total.f_m[d] += share.f_m[d];
            total.f_w[d] += share.f_w[d];
        }
    }
    EXPECT_NEAR( total.m_s, 600.0, 1e-12 );
    EXPECT_NEAR( total.m_w, 50.0, 1e-13 );
    EXPECT_NEAR( total.mv_w[1], 50.0 * 0.4, 1e-13 );
    EXPECT_NEAR( total.f_m[0], 100.0, 1e-9 );
    EXPECT_NEAR( total.f_m[1], -6500.0, 1e-9 );
    EXPECT_NEAR( total.f_w[0], 0.0, 1e-9 );
    EXPECT_NEAR( total.f_w[1], -2500.0, 1e-9 );
}

//---------------------------------------------------------------------------//
// Steps 2 and 4: n S, the drag (n S)^2 mu V / k_bar and the lock.
TEST( NodalWater, water_fraction_drag_and_lock )
{
    // m_w = 50 kg in V = 0.25 m^3: n S = 0.2; q = k_bar V = 0.25e-12 m^4:
    // Q = 0.04 x 1e-3 x 0.0625 / 0.25e-12 = 1e7 kg/s.
    const auto water = ph::nodalWater( ph::waterFraction( 50.0, 0.25, 1000.0 ),
                                       0.25, 0.25e-12, 1.0e-3 );
    EXPECT_DOUBLE_EQ( water.nS, 0.2 );
    EXPECT_FALSE( water.locked );
    EXPECT_NEAR( water.drag, 1.0e7, 1e-6 );
    const auto dry = ph::nodalWater( ph::waterFraction( 50.0, 0.25, 1000.0 ),
                                     0.25, 0.0, 1.0e-3 );
    EXPECT_TRUE( dry.locked );
    EXPECT_EQ( dry.drag, 0.0 );
}

TEST( NodalWater, seepage_of_a_prescribed_flux_and_remapped_velocity )
{
    // q = 1e-4 m/s into n S = 0.2: w = q / (n S) = 5e-4 m/s.
    EXPECT_DOUBLE_EQ( ph::tiedSeepage( 1.0e-4, 50.0, 600.0, 0.25, 1000.0 ),
                      5.0e-4 );
    EXPECT_EQ( ph::tiedSeepage( 1.0e-4, 0.0, 600.0, 0.25, 1000.0 ), 0.0 );
    // No water (below the floor): the water moves with the solid.
    EXPECT_FALSE( ph::hasWater( 1.0e-13 * 600.0, 600.0 ) );
    EXPECT_TRUE( ph::hasWater( 1.0e-11 * 600.0, 600.0 ) );
    EXPECT_EQ( ph::remappedWaterVelocity( 0.1, 5.0, 1.0e-13, 600.0, false, 0.0,
                                          0.25, 1000.0 ),
               0.1 );
    // Tied: v_s + the seepage; free: momentum over mass.
    EXPECT_DOUBLE_EQ( ph::remappedWaterVelocity( 0.1, 5.0, 50.0, 600.0, true,
                                                 1.0e-4, 0.25, 1000.0 ),
                      0.1 + 5.0e-4 );
    EXPECT_DOUBLE_EQ( ph::remappedWaterVelocity( 0.1, 5.0, 50.0, 600.0, false,
                                                 1.0e-4, 0.25, 1000.0 ),
                      0.1 );
}

//---------------------------------------------------------------------------//
// Step 10: the wave speeds.
TEST( WaveSpeeds, dry_saturated_and_unsaturated_points )
{
    // E = 1e7, nu = 0.25: E_c = E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 1.2e7.
    const auto soil = ph::elasticParams( 1.0e7, 0.25, 2000.0 );
    EXPECT_NEAR( soil.constrainedModulus(), 1.2e7, 1e-6 );
    EXPECT_NEAR( ph::waveSpeedDry( soil, 500.0, 0.25, 0.25 ),
                 std::sqrt( 6.0e3 ), 1e-12 );
    // Stretched to 4x its initial volume (rho 4x lower): the moduli fall
    // 4x with it, so the wave keeps its speed; constant moduli make it 2x
    // faster.
    EXPECT_NEAR( ph::waveSpeedDry( soil, 500.0, 1.0, 0.25 ), std::sqrt( 6.0e3 ),
                 1e-12 );
    auto constant = soil;
    constant.moduli_fall_with_dilation = false;
    EXPECT_NEAR( ph::waveSpeedDry( constant, 500.0, 1.0, 0.25 ),
                 2.0 * std::sqrt( 6.0e3 ), 1e-12 );
    // Saturated (dS/dp = 0, S = 1), n = 0.4, K_w = 2e9, rho_m = 2000:
    // mixture sqrt((1.2e7 + 2e9 / 0.4) / 2000) = sqrt(2.506e6) m/s, water
    // sqrt(2e9 / 1000) = sqrt(2e6) m/s: the mixture's.
    EXPECT_NEAR(
        ph::twoPhaseWaveSpeed( 1.2e7, 2000.0, 1000.0, 0.4, 1.0, 0.0, 2.0e9 ),
        std::sqrt( 2.506e6 ), 1e-9 );
    // Unsaturated, S = 0.5, dS/dp = 1e-5 /Pa: compressibility
    // 1e-5 + 2.5e-10 = 1.000025e-5 /Pa; mixture
    // sqrt((1.2e7 + 0.25 / (0.4 x 1.000025e-5)) / 2000) m/s.
    const double compressibility = 1.000025e-5;
    EXPECT_NEAR(
        ph::twoPhaseWaveSpeed( 1.2e7, 2000.0, 1000.0, 0.4, 0.5, 1.0e-5, 2.0e9 ),
        std::sqrt( ( 1.2e7 + 0.25 / ( 0.4 * compressibility ) ) / 2000.0 ),
        1e-9 );
    // A soft, light skeleton: the pore-water wave sqrt(S / (c rho_w)) wins.
    EXPECT_NEAR(
        ph::twoPhaseWaveSpeed( 1.0e3, 2000.0, 1000.0, 0.4, 0.5, 1.0e-5, 2.0e9 ),
        std::sqrt( 0.5 / ( compressibility * 1000.0 ) ), 1e-9 );
    // The step's rule uses the saturated stiffness at the point's density
    // rho_m = m_s / V + n S rho_w.
    ph::WaterParams water;
    water.bulk_modulus = 2.0e9;
    EXPECT_NEAR(
        ph::waveSpeedTwoPhase( soil, water, 400.0, 0.25, 0.25, 0.4, 1.0 ),
        std::sqrt( ( 1.2e7 + 1.0 / ( 0.4 * 5.0e-10 ) ) / 2000.0 ), 1e-9 );
    // The same point at twice its initial volume (V0 = 0.125): the
    // skeleton's E_c halves; at half of it (V0 = 0.5) it stays.
    EXPECT_NEAR(
        ph::waveSpeedTwoPhase( soil, water, 400.0, 0.25, 0.125, 0.4, 1.0 ),
        std::sqrt( ( 0.6e7 + 1.0 / ( 0.4 * 5.0e-10 ) ) / 2000.0 ), 1e-9 );
    EXPECT_NEAR(
        ph::waveSpeedTwoPhase( soil, water, 400.0, 0.25, 0.5, 0.4, 1.0 ),
        std::sqrt( ( 1.2e7 + 1.0 / ( 0.4 * 5.0e-10 ) ) / 2000.0 ), 1e-9 );
    // h / (c + |v|).
    EXPECT_DOUBLE_EQ( ph::pointTimeStep( 0.5, 95.0, 3.0, 4.0 ), 0.005 );
}

// Step 3: the PIC share scales with dt / the explicit CFL limit, so the
// damping per second depends on neither the step nor the scheme: a step of
// 20 limits (the semi-implicit scheme's) blends as 20 steps of one would.
TEST( WaveSpeeds, flip_fraction_scales_with_the_step )
{
    EXPECT_DOUBLE_EQ( ph::stepFlipFraction( 0.99, 1.0e-3, 1.0e-3 ), 0.99 );
    EXPECT_NEAR( ph::stepFlipFraction( 0.99, 2.0e-3, 1.0e-3 ), 0.99 * 0.99,
                 1e-15 );
    double twenty_steps = 1.0;
    for ( int k = 0; k < 20; ++k )
        twenty_steps *= ph::stepFlipFraction( 0.99, 1.0e-3, 1.0e-3 );
    EXPECT_NEAR( ph::stepFlipFraction( 0.99, 20.0e-3, 1.0e-3 ), twenty_steps,
                 1e-14 );
    EXPECT_NEAR( ph::stepFlipFraction( 0.99, 0.05e-3, 1.0e-3 ),
                 1.0 - 0.01 / 20.0, 1e-15 );
    EXPECT_DOUBLE_EQ( ph::stepFlipFraction( 0.99, 1.0e-3, 0.0 ), 0.99 );
}

//---------------------------------------------------------------------------//
// Steps 6 and 7 of the point update.
TEST( PointWater, volume_rate_porosity_and_source )
{
    // r = n S div v_w + (1 - n) S div v_s.
    const double L[2][2] = { { 0.01, 0.3 }, { -0.2, 0.03 } };
    EXPECT_DOUBLE_EQ( ph::waterVolumeRate( 0.4, 0.5, 0.1, L ),
                      0.4 * 0.5 * 0.1 + 0.6 * 0.5 * 0.04 );
    // Eq. 2: (1 - n) V is constant.
    const double n = ph::porosityAfterStep( 0.4, 1.02 );
    EXPECT_NEAR( ( 1.0 - n ) * 1.02, 0.6, 1e-15 );
    EXPECT_LT( ph::porosityAfterStep( 0.4, 0.99 ), 0.4 );
    // V source = V0 rate weight, whatever V.
    EXPECT_NEAR( ph::inflowSource( 1.0e-3, 0.5, 0.25, 0.2 ) * 0.2,
                 1.0e-3 * 0.5 * 0.25, 1e-19 );
}

TEST( PointWater, pressure_rules )
{
    // Saturated: explicit dp = volume change K_w / n (1e-6 x 2e9 / 0.4).
    auto r = ph::pointPressureAfterStep( 1.0e3, 7.0, 1.0e-6, 0.4, 2.0e9, true,
                                         false, false, 0.0 );
    EXPECT_DOUBLE_EQ( r.p_w, 1.0e3 + 5.0e3 );
    EXPECT_FALSE( r.capped );
    // Unsaturated: Newton's increment.
    r = ph::pointPressureAfterStep( -2.0e3, 700.0, 1.0e-6, 0.4, 2.0e9, false,
                                    false, false, 0.0 );
    EXPECT_DOUBLE_EQ( r.p_w, -1.3e3 );
    // A ponding inflow caps p_w > 0 at 0 and reports the free value.
    r = ph::pointPressureAfterStep( -100.0, 700.0, 1.0e-6, 0.4, 2.0e9, false,
                                    true, false, 0.0 );
    EXPECT_EQ( r.p_w, 0.0 );
    EXPECT_TRUE( r.capped );
    EXPECT_DOUBLE_EQ( r.p_w_free, 600.0 );
    // Below 0 no cap.
    r = ph::pointPressureAfterStep( -1000.0, 700.0, 1.0e-6, 0.4, 2.0e9, false,
                                    true, false, 0.0 );
    EXPECT_DOUBLE_EQ( r.p_w, -300.0 );
    EXPECT_FALSE( r.capped );
    // A prescribed pressure replaces everything.
    r = ph::pointPressureAfterStep( -1000.0, 700.0, 1.0e-6, 0.4, 2.0e9, true,
                                    false, true, -5.0e3 );
    EXPECT_EQ( r.p_w, -5.0e3 );
}

} // namespace
