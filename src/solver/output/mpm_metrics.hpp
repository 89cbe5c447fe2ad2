#ifndef MPM_METRICS_HPP
#define MPM_METRICS_HPP

#include <case/mpm_case_config.hpp>
#include <solver/output/mpm_run_observer.hpp>

#include <nlohmann/json.hpp>

namespace mpm
{
//! Case metrics from the final particle state: displacement statistics
//! and the area of material that moved more than `moved_threshold_m`.
nlohmann::json deformationMetrics( const HostSnapshot& snapshot,
                                   double moved_threshold_m );

/*!
  \brief The largest pore pressure and the largest 99th percentile of the
  active points' p_w over the snapshots it has seen (two-phase), Pa, with
  the simulated times at which they occurred.
*/
struct PorePressureExtremes
{
    double max_pa = -1.0e300;
    double max_time_s = 0.0;
    double p99_pa = -1.0e300;
    double p99_time_s = 0.0;
    bool seen = false;

    //! Takes in the snapshot at simulated time `time_s`.
    void add( const HostSnapshot& snapshot, double time_s );
    //! The metrics.json keys pore_pressure_max_pa, pore_pressure_p99_pa
    //! and their times (nothing if no two-phase snapshot was seen).
    void write( nlohmann::json& metrics ) const;
};

//! JSON of one stage summary; with `two_phase`, its water balance.
nlohmann::json stageMetrics( const StageSummary& stage, bool two_phase );

//! JSON of a water balance (m^3 per metre out of plane): the stored water
//! at the start and end, each term, the closure error and its ratio to
//! the largest term.
nlohmann::json waterBalanceMetrics( const physics::WaterBalance& water );

} // namespace mpm

#endif // MPM_METRICS_HPP
