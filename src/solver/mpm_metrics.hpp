#ifndef MPM_METRICS_HPP
#define MPM_METRICS_HPP

#include <io/mpm_case_config.hpp>
#include <solver/mpm_run_observer.hpp>

#include <nlohmann/json.hpp>

namespace mpm
{
//! Case metrics from the final particle state: displacement statistics
//! and the area of material that moved more than `moved_threshold_m`.
nlohmann::json deformationMetrics( const HostSnapshot& snapshot,
                                   double moved_threshold_m );

//! JSON of one stage summary.
nlohmann::json stageMetrics( const StageSummary& stage );

} // namespace mpm

#endif // MPM_METRICS_HPP
