#include <mpm_terzaghi_error.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( Terzaghi );

//! Captures snapshots at given stage times.
template <class ExecSpace>
class TimeProbe : public mpm::RunObserver
{
  public:
    TimeProbe( const mpm::Simulation<ExecSpace>& sim,
               std::vector<double> probe_times )
        : _sim( sim )
        , times( std::move( probe_times ) )
    {
    }
    void onStep( const mpm::RunProgress& progress ) override
    {
        while ( snapshots.size() < times.size() &&
                progress.stage_time_s >= times[snapshots.size()] )
            snapshots.push_back( mpm::hostSnapshot( _sim ) );
    }
    const mpm::Simulation<ExecSpace>& _sim;
    std::vector<double> times;
    std::vector<mpm::HostSnapshot> snapshots;
};

//---------------------------------------------------------------------------//
// Isochrones at Tv = 0.05 ... 1 against the series solution (20 cells).
TYPED_TEST( Terzaghi, isochrones_match_series_solution )
{
    using exec_space = TypeParam;
    const double K_w = 2.0e9, n = 0.3, E_c = 1.0e7, H = 1.0;
    const double m_v = 1.0 / E_c, beta = 1.0 / K_w;
    const double c_v = 1.0e-3 / ( 9810.0 * ( m_v + n * beta ) );
    const double p0 = 1.0e4 * m_v / ( m_v + n * beta );
    const double t_ramp = 0.004;
    const std::vector<double> Tv = { 0.05, 0.1, 0.2, 0.5, 1.0 };
    std::vector<double> times;
    for ( const double T : Tv )
        times.push_back( T * H * H / c_v + 0.5 * t_ramp );
    const int cells = 20;
    auto config =
        mpm_test::terzaghiCase( cells, K_w, times.back() + 1e-4, t_ramp );

    mpm::Simulation<exec_space> sim( config );
    TimeProbe<exec_space> probe( sim, times );
    mpm::runStages( sim, config, probe );
    ASSERT_EQ( probe.snapshots.size(), Tv.size() );

    for ( std::size_t k = 0; k < Tv.size(); ++k )
    {
        const auto error = mpm_test::terzaghiError( probe.snapshots[k], H,
                                                    H / cells, p0, Tv[k] );
        std::printf( "Terzaghi %d cells, Tv = %.2f: relative L2 error %.4f "
                     "(cells), %.4f (points)\n",
                     cells, Tv[k], error.cell, error.point );
        // Achieved: cells 0.08-0.11 %, points 0.11-0.13 % (the cell's
        // pressure slope, solver.cell_pressure_slope; a uniform pressure per
        // cell gave points 2.3-2.4 %).
        EXPECT_LT( error.cell, 0.003 ) << "Tv = " << Tv[k];
        EXPECT_LT( error.point, 0.004 ) << "Tv = " << Tv[k];
    }
    // Degree of consolidation from the mean pore pressure.
    const auto& last = probe.snapshots.back();
    double mean_p = 0.0;
    for ( int p = 0; p < last.num_points; ++p )
        mean_p += last.p_w[p] / last.num_points;
    const double degree = 1.0 - mean_p / p0;
    std::printf( "degree of consolidation %.5f, analytic %.5f\n", degree,
                 mpm_test::terzaghiDegree( Tv.back() ) );
    // Achieved: 2e-5 (0.93124 against 0.93126).
    EXPECT_NEAR( degree, mpm_test::terzaghiDegree( Tv.back() ), 1.0e-4 );
}

} // namespace
