#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace
{
MPM_TEST_BACKEND_SUITE( SaturatedColumn );

//! Cell means (by initial height) of a point field.
std::map<int, std::pair<double, double>>
cellMeans( const mpm::HostSnapshot& snap, const std::vector<double>& field,
           const int stride, const int component, const double h )
{
    std::map<int, std::array<double, 3>> sums; // value, y0, count
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const double y0 = snap.x[2 * p + 1] - snap.displacement[2 * p + 1];
        auto& s = sums[static_cast<int>( y0 / h )];
        s[0] += field[stride * p + component];
        s[1] += y0;
        s[2] += 1.0;
    }
    std::map<int, std::pair<double, double>> means; // cell -> (y0, value)
    for ( const auto& [cell, s] : sums )
        means[cell] = { s[1] / s[2], s[0] / s[2] };
    return means;
}

//---------------------------------------------------------------------------//
// A saturated column under gravity, starting from p_w = 0, drains through
// its top surface to the hydrostatic state: p_w = rho_w g depth, v_w -> 0,
// effective stress sigma'_yy = -(rho_sat - rho_w) g depth (Bishop, S = 1).
template <class exec_space>
void settlesToHydrostatic( const mpm::TwoPhaseScheme scheme,
                           const double tolerance )
{
    const double H = 2.0, h = 0.1, g = 9.81, n = 0.3, rho_s = 2650.0;
    // 1.5 s: about 5 consolidation times H^2 / c_v
    mpm::StageConfig stage = mpm_test::stageConfig(
        "settle", mpm::StageType::Dynamic, 1.5, -g, 0.5 );
    auto config = mpm_test::columnCase(
        H, h, mpm_test::saturatedMaterial( 1.0e7, 0.3, rho_s, n, 1.0e-9 ),
        stage );
    config.analysis = mpm::AnalysisType::Saturated;
    config.solver.scheme = scheme;

    mpm::Simulation<exec_space> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const auto snap = mpm::hostSnapshot( sim );

    const double rho_w = 1000.0;
    const double rho_sat = ( 1 - n ) * rho_s + n * rho_w;
    const auto p_w = cellMeans( snap, snap.p_w, 1, 0, h );
    const auto s_yy = cellMeans( snap, snap.sigma, 4, 1, h );
    double p_w_error = 0.0, s_yy_error = 0.0;
    for ( const auto& [cell, mean] : p_w )
    {
        const double depth = H - mean.first;
        if ( cell >= static_cast<int>( H / h ) - 2 )
            continue; // the two cells below the drained surface
        const double expected = rho_w * g * depth;
        const double expected_s = -( rho_sat - rho_w ) * g * depth;
        p_w_error =
            std::max( p_w_error, std::abs( mean.second / expected - 1.0 ) );
        s_yy_error = std::max(
            s_yy_error, std::abs( s_yy.at( cell ).second / expected_s - 1.0 ) );
    }
    std::printf( "hydrostatic column: cell means off by %.2e (p_w), %.2e "
                 "(effective sigma_yy)\n",
                 p_w_error, s_yy_error );
    EXPECT_LT( p_w_error, tolerance );
    EXPECT_LT( s_yy_error, tolerance );
    double v_w_max = 0.0;
    for ( const double v : snap.v_w )
        v_w_max = std::max( v_w_max, std::abs( v ) );
    EXPECT_LT( v_w_max, 1.0e-5 ); // m/s, against K = 1e-2 m/s
}

// Achieved: 6.5e-3 (p_w), 6.4e-3 (sigma_yy).
TYPED_TEST( SaturatedColumn, settles_to_hydrostatic_pressure )
{
    settlesToHydrostatic<TypeParam>( mpm::TwoPhaseScheme::Explicit, 0.01 );
}

// The semi-implicit scheme (docs/formulation.md §9). Achieved: 6.5e-3
// (p_w), 6.4e-3 (sigma_yy), as the explicit scheme.
TYPED_TEST( SaturatedColumn, semi_implicit_settles_to_hydrostatic_pressure )
{
    settlesToHydrostatic<TypeParam>( mpm::TwoPhaseScheme::SemiImplicit, 0.01 );
}

//---------------------------------------------------------------------------//
// Undrained oedometric loading (k = 1e-14 m^2: consolidation time ~1e3 s
// against a 0.5 s run) of a sealed column: the water carries
// dp = B sigma_c with B = m_v / (m_v + n / K_w) (Skempton's B for 1D).
template <class exec_space>
void undrainedSkemptonB( const mpm::TwoPhaseScheme scheme,
                         const int cells_skipped, const double p_w_tolerance,
                         const double s_yy_tolerance )
{
    const double H = 1.0, h = 0.1, n = 0.3, E = 1.0e7, K_w = 2.0e7;
    mpm::StageConfig stage =
        mpm_test::stageConfig( "load", mpm::StageType::Dynamic, 0.5, 0.0, 0.3 );
    auto config = mpm_test::columnCase(
        H, h, mpm_test::saturatedMaterial( E, 0.0, 2650.0, n, 1.0e-14 ),
        stage );
    config.analysis = mpm::AnalysisType::Saturated;
    config.water.bulk_modulus_pa = K_w;
    config.grid.cells[1] = static_cast<int>( H / h + 0.5 ); // sealed top edge
    mpm::PointLoad load;
    load.points.box_m = { mpm::Point2{ -1.0, H - 0.5 * h },
                          mpm::Point2{ 1.0, H } };
    load.traction_pa = { 0.0, -1.0e4 };
    load.length_m = h;
    load.time_function = { { 0.0, 0.0 }, { 0.05, 1.0 } };
    config.stages[0].loads = { load };
    config.solver.scheme = scheme;

    mpm::Simulation<exec_space> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const auto snap = mpm::hostSnapshot( sim );

    const double m_v = 1.0 / E, B = m_v / ( m_v + n / K_w );
    // Below the loaded top cell (whose points carry the load) the total
    // vertical stress is the full load: water and skeleton share it.
    const auto p_w = cellMeans( snap, snap.p_w, 1, 0, h );
    const auto s_yy = cellMeans( snap, snap.sigma, 4, 1, h );
    double p_w_error = 0.0, s_yy_error = 0.0;
    for ( const auto& [cell, mean] : p_w )
    {
        std::printf( "  cell %d: p_w off by %.2e, sigma'_yy by %.2e\n", cell,
                     mean.second / ( B * 1.0e4 ) - 1.0,
                     s_yy.at( cell ).second / ( -( 1.0 - B ) * 1.0e4 ) - 1.0 );
        if ( cell >= static_cast<int>( H / h ) - cells_skipped )
            continue;
        p_w_error = std::max( p_w_error,
                              std::abs( mean.second / ( B * 1.0e4 ) - 1.0 ) );
        s_yy_error =
            std::max( s_yy_error, std::abs( s_yy.at( cell ).second /
                                                ( -( 1.0 - B ) * 1.0e4 ) -
                                            1.0 ) );
    }
    std::printf( "Skempton's B = %.4f: cell means off by %.2e (p_w), %.2e "
                 "(effective sigma_yy)\n",
                 B, p_w_error, s_yy_error );
    EXPECT_LT( p_w_error, p_w_tolerance );
    EXPECT_LT( s_yy_error, s_yy_tolerance );
}

// Every cell below the loaded one. Achieved: 7.2e-4 (p_w), 5.8e-3
// (sigma_yy).
TYPED_TEST( SaturatedColumn, undrained_load_is_carried_by_skempton_b )
{
    undrainedSkemptonB<TypeParam>( mpm::TwoPhaseScheme::Explicit, 1, 0.002,
                                   0.01 );
}

// The semi-implicit scheme, every cell below the loaded one. Achieved:
// 8.2e-4 (p_w), 6.5e-3 (sigma_yy), both in the cell just below it. With
// one pressure unknown per node an approximate projection puts the three
// cells below the load 0.2 %, 1.2 %, 5 % off in p_w and 1.6 %, 8 %, 35 % in
// sigma'_yy: hence one per cell (docs/formulation.md §9).
TYPED_TEST( SaturatedColumn, semi_implicit_undrained_load_is_carried_by_b )
{
    undrainedSkemptonB<TypeParam>( mpm::TwoPhaseScheme::SemiImplicit, 1, 0.002,
                                   0.02 );
}

} // namespace
