#ifndef MPM_TEST_TIME_PROBE_HPP
#define MPM_TEST_TIME_PROBE_HPP

#include <solver/drivers/mpm_run_stages.hpp>

#include <utility>
#include <vector>

namespace mpm_test
{
//! Captures snapshots of a simulation once its stage time reaches each of
//! the given times (within `tolerance`, relative).
template <class ExecSpace>
struct TimeProbe : public mpm::RunObserver
{
    TimeProbe( const mpm::Simulation<ExecSpace>& simulation,
               std::vector<double> probe_times, const double tolerance = 0.0 )
        : sim( simulation )
        , times( std::move( probe_times ) )
        , relative_tolerance( tolerance )
    {
    }
    void onStep( const mpm::RunProgress& progress ) override
    {
        while ( snapshots.size() < times.size() &&
                progress.stage_time_s >=
                    times[snapshots.size()] * ( 1.0 - relative_tolerance ) )
            snapshots.push_back( mpm::hostSnapshot( sim ) );
    }

    const mpm::Simulation<ExecSpace>& sim;
    std::vector<double> times;
    double relative_tolerance;
    std::vector<mpm::HostSnapshot> snapshots;
};

} // namespace mpm_test

#endif // MPM_TEST_TIME_PROBE_HPP
