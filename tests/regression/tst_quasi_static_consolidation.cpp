#include <mpm_terzaghi_error.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_time_probe.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

// The quasi-static scheme (docs/formulation.md §11) on Terzaghi's column at
// a real permeability, K = 1e-8 m/s: a day of consolidation in 100-200 steps.
namespace
{
MPM_TEST_BACKEND_SUITE( QuasiStaticConsolidation );

const double K_w = 2.0e9, n = 0.3, E_c = 1.0e7, H = 1.0;
const double m_v = 1.0 / E_c;
const double K_s = 1.0e-8; // m/s
const double c_v = K_s / ( 9810.0 * ( m_v + n / K_w ) );
const double p0 = 1.0e4 * m_v / ( m_v + n / K_w );
const int cells = 20;

/*!
  The scheme's discrete counterpart: backward Euler over `steps` steps of
  dt on the column's cells (cell-centred, the drained face half a cell above
  the top cell's centre), the load's excess pressure appearing one step
  late (the relaxation takes a load at held p_w; the flow stores the water
  it squeezed out in the next step). Returns p / p0 per cell from the top
  after the last step.
*/
std::vector<double> backwardEulerLagged( const double dt, const int steps )
{
    const double a = c_v * dt / ( ( H / cells ) * ( H / cells ) );
    std::vector<double> p( cells, 0.0 );
    for ( int step = 1; step <= steps; ++step )
    {
        std::vector<double> rhs = p;
        if ( step == 2 )
            for ( double& r : rhs )
                r += 1.0;
        // Tridiagonal (Thomas): -a p[i-1] + (1 + a (2 or 1 + ...)) p[i] ...
        std::vector<double> lower( cells, -a ), upper( cells, -a ),
            diag( cells, 1.0 + 2.0 * a );
        diag[0] = 1.0 + 3.0 * a; // the drained face at h / 2
        diag[cells - 1] = 1.0 + a;
        for ( int i = 1; i < cells; ++i )
        {
            const double w = lower[i] / diag[i - 1];
            diag[i] -= w * upper[i - 1];
            rhs[i] -= w * rhs[i - 1];
        }
        p[cells - 1] = rhs[cells - 1] / diag[cells - 1];
        for ( int i = cells - 2; i >= 0; --i )
            p[i] = ( rhs[i] - upper[i] * p[i + 1] ) / diag[i];
    }
    return p;
}

//! Cell means of p_w / p0 from the top of a snapshot of the column.
std::vector<double> cellMeans( const mpm::HostSnapshot& snap )
{
    std::map<int, std::pair<double, int>> sums;
    for ( int q = 0; q < snap.num_points; ++q )
    {
        const double z =
            H - ( snap.x[2 * q + 1] - snap.displacement[2 * q + 1] );
        auto& s = sums[static_cast<int>( std::floor( z * cells / H ) )];
        s.first += snap.p_w[q] / p0;
        ++s.second;
    }
    std::vector<double> means;
    for ( const auto& [cell, s] : sums )
        means.push_back( s.first / s.second );
    return means;
}

struct ConsolidationRun
{
    std::vector<double> error;     //!< point-wise L2 against the series
    std::vector<double> discrete;  //!< cell means against backward Euler
    double water_closure_m3 = 0.0; //!< the ledger's closure
    double water_moved_m3 = 0.0;   //!< the water that left the column
    long steps = 0;
};

const std::vector<double> Tv = { 0.05, 0.1, 0.2, 0.5, 1.0 };

//! Runs the column to Tv = 1 at steps of dt_Tv (in Tv).
template <class ExecSpace>
ConsolidationRun consolidate( const double dt_Tv )
{
    const double dt = dt_Tv * H * H / c_v;
    std::vector<double> times;
    for ( const double T : Tv )
        times.push_back( T * H * H / c_v );
    auto config = mpm_test::terzaghiCase( cells, K_w, times.back(), 0.0 );
    config.materials[0].permeability_m2 = K_s * 1.0e-3 / ( 1000.0 * 9.81 );
    config.stages[0].materials = config.materials;
    config.stages[0].loads[0].time_function = { { 0.0, 1.0 } };
    config.stages[0].snapshot_times_s = times;
    config.solver.scheme = mpm::TwoPhaseScheme::QuasiStatic;
    config.solver.dt_s = dt;

    mpm::Simulation<ExecSpace> sim( config );
    mpm_test::TimeProbe<ExecSpace> probe( sim, times, 1.0e-6 );
    const mpm::RunSummary summary = mpm::runStages( sim, config, probe );
    EXPECT_EQ( probe.snapshots.size(), Tv.size() );
    ConsolidationRun run;
    run.steps = sim.step;
    for ( std::size_t k = 0; k < probe.snapshots.size(); ++k )
    {
        run.error.push_back( mpm_test::terzaghiError( probe.snapshots[k], H,
                                                      H / cells, p0, Tv[k] )
                                 .point );
        const std::vector<double> mpm = cellMeans( probe.snapshots[k] );
        const std::vector<double> be = backwardEulerLagged(
            dt, static_cast<int>( std::lround( Tv[k] / dt_Tv ) ) );
        double d2 = 0.0, r2 = 0.0;
        for ( int c = 0; c < cells && c < int( mpm.size() ); ++c )
        {
            d2 += ( mpm[c] - be[c] ) * ( mpm[c] - be[c] );
            r2 += be[c] * be[c];
        }
        run.discrete.push_back( std::sqrt( d2 / r2 ) );
        std::printf( "quasi-static Terzaghi dt = %.4f Tv: Tv = %.2f, L2 "
                     "against the series %.4f, against backward Euler %.4f\n",
                     dt_Tv, Tv[k], run.error.back(), run.discrete.back() );
    }
    const mpm::physics::WaterBalance& w = summary.water;
    run.water_closure_m3 = w.closureError();
    run.water_moved_m3 = std::abs( w.flow_in );
    return run;
}

// Achieved at dt = 0.005 Tv (200 steps): 0.0275, 0.0182, 0.0158, 0.0214,
// 0.0281 against the series, which backward Euler's error with the load a
// step late explains (0.0284, 0.0187, 0.0161, 0.0209, 0.0293 on its own):
// the cell means within 0.0007-0.0017 of that discrete solution (0.0036 at
// 0.01 Tv); at 0.01 Tv 2.06 times the early error (first order in time);
// the water ledger closes to 1e-17 m^3 of 4.6e-5 m^3 squeezed out.
TYPED_TEST( QuasiStaticConsolidation, day_long_steps_follow_backward_euler )
{
    const ConsolidationRun fine = consolidate<TypeParam>( 0.005 );
    const ConsolidationRun coarse = consolidate<TypeParam>( 0.01 );
    EXPECT_EQ( fine.steps, 200 );
    for ( std::size_t k = 0; k < fine.error.size(); ++k )
    {
        EXPECT_LT( fine.error[k], 0.04 ) << "Tv = " << Tv[k];
        EXPECT_LT( fine.discrete[k], 0.012 ) << "Tv = " << Tv[k];
        EXPECT_LT( coarse.discrete[k], 0.012 ) << "Tv = " << Tv[k];
    }
    // First order in time: half the step, half the early error.
    const double ratio = coarse.error[0] / fine.error[0];
    std::printf( "error ratio at Tv = 0.05: %.3f\n", ratio );
    EXPECT_GT( ratio, 1.7 );
    EXPECT_LT( ratio, 2.3 );
    std::printf( "water closure %.3e m^3 of %.3e m^3 moved\n",
                 fine.water_closure_m3, fine.water_moved_m3 );
    EXPECT_LT( std::abs( fine.water_closure_m3 ),
               1.0e-6 * fine.water_moved_m3 );
}

} // namespace
