#ifndef MPM_STAGE_STATE_JSON_HPP
#define MPM_STAGE_STATE_JSON_HPP

// The stage-loop state (StageLoopState and the records it holds) as JSON,
// for the checkpoint file. Each field is listed once, below; the JSON keys
// are the member names.

#include <records/mpm_stage_state.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace mpm
{
namespace physics
{
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( WaterBalance, stored_start, stored_end,
                                    carried_off_start, carried_off_end,
                                    point_inflow, runoff, prescribed, flow_in )
} // namespace physics

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( StageSummary, name, type, steps, duration_s,
                                    dt_min_s, dt_max_s, ke_ratio, converged,
                                    stop_reason, max_speed_m_per_s, water,
                                    speed_percentile, static_speed_m_per_s,
                                    speed_at_percentile_m_per_s,
                                    points_not_below_static_speed,
                                    allowed_points_not_below )

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( RunProgress, stage, stage_index, step,
                                    stage_step, time_s, stage_time_s,
                                    stage_duration_s, dt_s, kinetic_energy_j,
                                    active_points )

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( RunSummary, stages, steps, dt_min_s,
                                    dt_max_s, interrupted, water )

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( StageLoopState, stage, stage_started,
                                    progress, stage_summary, ke_max,
                                    below_since, has_moved, static_since,
                                    next_snapshot_s, next_checkpoint_s, run )

/*!
  \brief The loop state as compact JSON text (to_json above), exact: a
  finite double as the shortest text that reads back to the same bits, a
  non-finite one as the string "nan", "inf" or "-inf" (JSON has no such
  numbers; nlohmann would write null).
*/
std::string stageLoopStateJson( const StageLoopState& state );

/*!
  \brief Reads stageLoopStateJson's text strictly: every field present,
  none unknown, each of its type (integers in range; a double also as
  "nan", "inf" or "-inf").
  \throw std::runtime_error "checkpoint '<file>': ..." naming the field
  (e.g. "run.stages[1].steps"), or saying the text is not JSON.
*/
StageLoopState parseStageLoopState( const std::string& text,
                                    const std::string& file );

} // namespace mpm

#endif // MPM_STAGE_STATE_JSON_HPP
