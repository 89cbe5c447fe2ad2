#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace
{
MPM_TEST_BACKEND_SUITE( ElasticColumn );

const double height = 4.0, h = 0.1, rho = 2000.0, g = 9.81;
const double E = 1.0e8, nu = 0.3;

// A damped (quasi-static) stage under gravity g of the column.
mpm::StageConfig dampedStage( const std::string& name, const double duration_s )
{
    mpm::StageConfig stage;
    stage.name = name;
    stage.type = mpm::StageType::QuasiStatic;
    stage.gravity_m_per_s2 = { 0.0, -g };
    stage.damping = 0.1;
    stage.duration_s = duration_s;
    return stage;
}

//---------------------------------------------------------------------------//
// Column under self-weight after a quasi-static stage: sigma_yy = -rho g d,
// sigma_xx = K0 sigma_yy, settlement u(y) = rho g (H y - y^2 / 2) / E_c.
TYPED_TEST( ElasticColumn, geostatic_stress_and_settlement )
{
    using exec_space = TypeParam;
    mpm::StageConfig stage = dampedStage( "gravity", 20.0 );
    stage.ke_ratio_tolerance = 1.0e-9;
    auto config = mpm_test::columnCase(
        height, h, mpm_test::elasticMaterial( E, nu, rho ), stage );

    mpm::Simulation<exec_space> sim( config );
    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    ASSERT_TRUE( summary.stages[0].converged )
        << "ke ratio " << summary.stages[0].ke_ratio;

    const auto snap = mpm::hostSnapshot( sim );
    const double E_c = E * ( 1 - nu ) / ( ( 1 + nu ) * ( 1 - 2 * nu ) );
    const double K0 = nu / ( 1 - nu );
    // Cell averages of stress against the value at the cell centre.
    std::map<int, std::pair<double, int>> syy_cell, sxx_cell;
    double max_settlement_error = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const double y0 = snap.x[2 * p + 1] - snap.displacement[2 * p + 1];
        const int cell = static_cast<int>( y0 / h );
        syy_cell[cell].first += snap.sigma[4 * p + 1];
        syy_cell[cell].second += 1;
        sxx_cell[cell].first += snap.sigma[4 * p + 0];
        sxx_cell[cell].second += 1;
        // Settlement of the top row against the 1D solution.
        if ( y0 > height - h )
        {
            const double u_exact =
                rho * g * ( height * y0 - 0.5 * y0 * y0 ) / E_c;
            const double error =
                std::abs( -snap.displacement[2 * p + 1] - u_exact ) / u_exact;
            max_settlement_error = std::max( max_settlement_error, error );
        }
    }
    const int num_cells = static_cast<int>( height / h + 0.5 );
    ASSERT_EQ( static_cast<int>( syy_cell.size() ), num_cells );
    for ( const auto& [cell, sum] : syy_cell )
    {
        if ( cell == 0 || cell == num_cells - 1 )
            continue; // away from the ends
        const double depth = height - ( cell + 0.5 ) * h;
        const double expected = -rho * g * depth;
        const double syy = sum.first / sum.second;
        EXPECT_NEAR( syy, expected, 0.01 * std::abs( expected ) )
            << "cell " << cell;
        const double sxx = sxx_cell[cell].first / sxx_cell[cell].second;
        EXPECT_NEAR( sxx, K0 * expected, 0.01 * std::abs( K0 * expected ) )
            << "cell " << cell;
    }
    EXPECT_LT( max_settlement_error, 0.02 );
}

//---------------------------------------------------------------------------//
// The same column started from the geostatic field of initial_stress_k0 =
// 0.8 (not the elastic nu / (1 - nu) = 0.43 gravity loading gives): the
// field is in equilibrium under a level surface, so an undamped dynamic
// stage of about three wave periods (4 H / c = 0.06 s) keeps sigma_xx = 0.8
// sigma_yy and sigma_yy = -rho g d, and the column hardly moves (against
// the settlement rho g H^2 / 2 E_c of loading from zero stress, which
// would swing it by twice that).
TYPED_TEST( ElasticColumn, k0_field_is_kept_in_equilibrium )
{
    using exec_space = TypeParam;
    const double k0 = 0.8;
    mpm::StageConfig stage = dampedStage( "k0", 0.2 );
    stage.type = mpm::StageType::Dynamic;
    stage.damping = 0.0;
    stage.initial_stress_k0 = k0;
    auto config = mpm_test::columnCase(
        height, h, mpm_test::elasticMaterial( E, nu, rho ), stage );

    mpm::Simulation<exec_space> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    EXPECT_GT( sim.step, 100 );

    const auto snap = mpm::hostSnapshot( sim );
    const double E_c = E * ( 1 - nu ) / ( ( 1 + nu ) * ( 1 - 2 * nu ) );
    const double settlement = rho * g * height * height / ( 2.0 * E_c );
    double max_u = 0.0, max_ratio_error = 0.0, max_syy_error = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        max_u = std::max( max_u, std::abs( snap.displacement[2 * p + 1] ) );
        const double depth = height - snap.x[2 * p + 1];
        if ( depth < h || depth > height - h )
            continue; // away from the ends
        const double syy = snap.sigma[4 * p + 1];
        max_syy_error =
            std::max( max_syy_error,
                      std::abs( syy + rho * g * depth ) / ( rho * g * depth ) );
        max_ratio_error = std::max(
            max_ratio_error, std::abs( snap.sigma[4 * p + 0] / syy - k0 ) );
    }
    std::printf( "[ k0 column ] max |u_y| %.3e m (loading from zero: %.3e), "
                 "|sxx/syy - K0| %.2e, |syy + rho g d| / rho g d %.2e\n",
                 max_u, settlement, max_ratio_error, max_syy_error );
    EXPECT_LT( max_u, 0.01 * settlement );
    EXPECT_LT( max_ratio_error, 0.01 );
    EXPECT_LT( max_syy_error, 0.01 );
}

// A quasi-static stage started from that field is at rest from its first
// step (E_kin at rounding level, so its largest E_kin is noise too): it
// converges after one window (4 H / c = 0.062 s) and 20 steps, not at the
// end of its duration as "unconverged" (the ratio of rounding noise to its
// own peak stays near 1: 0.18 on a 5 m column over 5 s).
TYPED_TEST( ElasticColumn, k0_field_converges_at_once_in_a_quasi_static_stage )
{
    using exec_space = TypeParam;
    mpm::StageConfig stage = dampedStage( "k0", 1.0 );
    stage.initial_stress_k0 = 0.8;
    auto config = mpm_test::columnCase(
        height, h, mpm_test::elasticMaterial( E, nu, rho ), stage );

    mpm::Simulation<exec_space> sim( config );
    mpm::RunObserver observer;
    const auto summary = mpm::runStages( sim, config, observer );
    const double window_s = mpm::quasiStaticWindow( config, config.stages[0] );
    std::printf( "[ k0 column, quasi-static ] converged %d after %ld steps, "
                 "%.4f s (window %.4f s), ke ratio %.2e\n",
                 summary.stages[0].converged ? 1 : 0, summary.stages[0].steps,
                 summary.stages[0].duration_s, window_s,
                 summary.stages[0].ke_ratio );
    EXPECT_TRUE( summary.stages[0].converged );
    EXPECT_EQ( summary.stages[0].stop_reason, "kinetic_energy_ratio" );
    EXPECT_LT( summary.stages[0].duration_s, 2.0 * window_s );
}

} // namespace
