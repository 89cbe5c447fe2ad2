#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <map>

namespace
{
MPM_TEST_BACKEND_SUITE( ElasticColumn );

//---------------------------------------------------------------------------//
// Column under self-weight after a quasi-static stage: sigma_yy = -rho g d,
// sigma_xx = K0 sigma_yy, settlement u(y) = rho g (H y - y^2 / 2) / E_c.
TYPED_TEST( ElasticColumn, geostatic_stress_and_settlement )
{
    using exec_space = TypeParam;
    const double height = 4.0, h = 0.1, rho = 2000.0, g = 9.81;
    const double E = 1.0e8, nu = 0.3;
    mpm::StageConfig stage;
    stage.name = "gravity";
    stage.type = mpm::StageType::QuasiStatic;
    stage.gravity_m_per_s2 = { 0.0, -g };
    stage.damping = 0.1;
    stage.duration_s = 20.0;
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

} // namespace
