#ifndef MPM_TEST_RESTART_HPP
#define MPM_TEST_RESTART_HPP

// Helpers of the checkpoint / restart tests (regression/tst_restart.cpp,
// tst_restart_file.cpp, tst_restart_cli.cpp): the scratch folder, the
// block case with two stages, comparisons of two runs.
#include <mpm_test_cli.hpp>

#include <io/mpm_checkpoint.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <unistd.h>

namespace mpm_test
{
namespace restart
{
namespace fs = std::filesystem;

//! Per-process scratch folder (other runs of the suite may be running).
inline fs::path scratch()
{
    return fs::path( ::testing::TempDir() ) /
           ( "rainslide_restart_" + std::to_string( ::getpid() ) );
}

//! Removes the scratch folder when the test binary exits.
inline const struct ScratchCleanup
{
    ~ScratchCleanup()
    {
        std::error_code ignored;
        fs::remove_all( scratch(), ignored );
    }
} scratch_cleanup;

inline fs::path freshDir( const std::string& name )
{
    const fs::path dir = scratch() / name;
    fs::remove_all( dir );
    fs::create_directories( dir );
    return dir;
}

//! The test block (mpm_test::blockCaseText) with two dynamic stages, the
//! first `duration_s` long.
inline std::string blockCase( const std::string& solver_extra,
                              const double duration_s = 0.2 )
{
    const std::string snapshots = "snapshot_interval_s = 0.05\n";
    return mpm_test::blockCaseText(
        solver_extra, "\n" +
                          mpm_test::stageToml( "load", "dynamic",
                                               std::to_string( duration_s ) ) +
                          snapshots +
                          mpm_test::stageToml( "more", "dynamic", "0.1" ) +
                          snapshots );
}

//---------------------------------------------------------------------------//
//! Every array of two states: bitwise equal (exact) or within a relative
//! 1e-10 of the array's largest magnitude.
inline void expectSameState( const mpm::Checkpoint& a, const mpm::Checkpoint& b,
                             const bool exact )
{
    EXPECT_EQ( a.step, b.step );
    EXPECT_EQ( a.num_removed, b.num_removed );
    if ( exact )
        EXPECT_EQ( a.time_s, b.time_s );
    else
        EXPECT_NEAR( a.time_s, b.time_s, 1.0e-10 * a.time_s );
    ASSERT_EQ( a.arrays.size(), b.arrays.size() );
    for ( std::size_t k = 0; k < a.arrays.size(); ++k )
    {
        const mpm::CheckpointArray& x = a.arrays[k];
        const mpm::CheckpointArray& y = b.arrays[k];
        ASSERT_EQ( x.name, y.name );
        ASSERT_EQ( x.dims, y.dims ) << x.name;
        EXPECT_EQ( x.integers, y.integers ) << x.name;
        ASSERT_EQ( x.reals.size(), y.reals.size() ) << x.name;
        double scale = 0.0;
        for ( const double v : x.reals )
            scale = std::max( scale, std::abs( v ) );
        std::size_t differing = 0, first = 0;
        for ( std::size_t i = 0; i < x.reals.size(); ++i )
        {
            const bool same =
                exact ? std::memcmp( &x.reals[i], &y.reals[i],
                                     sizeof( double ) ) == 0
                      : std::abs( x.reals[i] - y.reals[i] ) <= 1.0e-10 * scale;
            if ( !same && differing++ == 0 )
                first = i;
        }
        EXPECT_EQ( differing, 0u )
            << x.name << ": " << differing << " of " << x.reals.size()
            << " values differ, first [" << first
            << "]: " << ( x.reals.empty() ? 0.0 : x.reals[first] ) << " vs "
            << ( y.reals.empty() ? 0.0 : y.reals[first] );
    }
}

//! Run summaries: equal counts, times equal (exact) or within 1e-10.
inline void expectSameSummary( const mpm::RunSummary& a,
                               const mpm::RunSummary& b, const bool exact )
{
    const auto near = [&]( const double x, const double y, const char* what )
    {
        if ( exact )
            EXPECT_EQ( x, y ) << what;
        else
            EXPECT_NEAR( x, y, 1.0e-10 * std::abs( x ) ) << what;
    };
    EXPECT_EQ( a.steps, b.steps );
    EXPECT_EQ( a.interrupted, b.interrupted );
    near( a.dt_min_s, b.dt_min_s, "dt_min_s" );
    near( a.dt_max_s, b.dt_max_s, "dt_max_s" );
    ASSERT_EQ( a.stages.size(), b.stages.size() );
    for ( std::size_t s = 0; s < a.stages.size(); ++s )
    {
        EXPECT_EQ( a.stages[s].name, b.stages[s].name );
        EXPECT_EQ( a.stages[s].steps, b.stages[s].steps );
        EXPECT_EQ( a.stages[s].converged, b.stages[s].converged );
        near( a.stages[s].duration_s, b.stages[s].duration_s, "duration_s" );
        near( a.stages[s].ke_ratio, b.stages[s].ke_ratio, "ke_ratio" );
    }
}

//! Step and time of the snapshots of `all` from index `from` on.
inline std::vector<std::pair<long, double>>
marks( const std::vector<mpm::RunProgress>& all, const std::size_t from )
{
    std::vector<std::pair<long, double>> out;
    for ( std::size_t k = from; k < all.size(); ++k )
        out.emplace_back( all[k].step, all[k].time_s );
    return out;
}

} // namespace restart
} // namespace mpm_test

#endif // MPM_TEST_RESTART_HPP
