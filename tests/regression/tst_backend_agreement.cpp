#include <mpm_test_backends.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

namespace
{
MPM_TEST_BACKEND_SUITE( BackendAgreement );

template <class ExecSpace>
mpm::HostSnapshot runShortSlope( const mpm::CaseConfig& config )
{
    mpm::Simulation<ExecSpace> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    return mpm::hostSnapshot( sim );
}

//---------------------------------------------------------------------------//
// A complete short run of the dry slope (Mohr–Coulomb, softening, yielding)
// on this backend agrees with Serial within a relative 1e-10.
TYPED_TEST( BackendAgreement, total_stress_slope_matches_serial )
{
    auto config =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/slope_total_stress.toml" );
    config.stages[0].duration_s = 0.3;
    config.stages[0].snapshot_interval_s = 0.0;
    const auto serial = runShortSlope<Kokkos::Serial>( config );
    const auto other = runShortSlope<TypeParam>( config );

    ASSERT_EQ( serial.num_points, other.num_points );
    auto compare = [&]( const std::vector<double>& a,
                        const std::vector<double>& b, const char* name )
    {
        ASSERT_EQ( a.size(), b.size() );
        double scale = 0.0;
        for ( const double value : a )
            scale = std::max( scale, std::abs( value ) );
        double max_diff = 0.0;
        for ( std::size_t k = 0; k < a.size(); ++k )
            max_diff = std::max( max_diff, std::abs( a[k] - b[k] ) );
        EXPECT_LE( max_diff, 1e-10 * scale )
            << name << " (scale " << scale << ")";
    };
    compare( serial.x, other.x, "position" );
    compare( serial.v, other.v, "velocity" );
    compare( serial.sigma, other.sigma, "stress" );
    compare( serial.eps_p_bar, other.eps_p_bar, "plastic shear strain" );
    compare( serial.vol, other.vol, "volume" );
    // The run must have yielded somewhere, or it tests little.
    double max_eps_p = 0.0;
    for ( const double e : serial.eps_p_bar )
        max_eps_p = std::max( max_eps_p, e );
    EXPECT_GT( max_eps_p, 1e-3 );
}

} // namespace
