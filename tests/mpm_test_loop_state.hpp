#ifndef MPM_TEST_LOOP_STATE_HPP
#define MPM_TEST_LOOP_STATE_HPP

// A stage-loop state with every field away from its default, for the
// tests of its JSON form and of the checkpoint file.
#include <records/mpm_stage_state.hpp>

#include <limits>
#include <string>

namespace mpm_test
{
//! A water balance with distinct values from `base` on.
inline mpm::physics::WaterBalance filledWaterBalance( const double base )
{
    mpm::physics::WaterBalance w;
    w.stored_start = base + 0.1;
    w.stored_end = base + 0.2;
    w.carried_off_start = base + 0.3;
    w.carried_off_end = base + 0.4;
    w.point_inflow = base + 0.5;
    w.runoff = base + 0.6;
    w.prescribed = base + 0.7;
    w.flow_in = base + 0.8;
    return w;
}

//! A stage summary with distinct values from `base` on.
inline mpm::StageSummary filledStageSummary( const double base,
                                             const std::string& name )
{
    mpm::StageSummary s;
    s.name = name;
    s.type = "quasi_static";
    s.steps = 1234567890123L + static_cast<long>( base );
    s.duration_s = base / 3.0;
    s.dt_min_s = base * 1.0e-7 / 7.0;
    s.dt_max_s = base * 1.0e-5 / 3.0;
    s.ke_ratio = base * 1.0e-9 / 11.0;
    s.converged = false;
    s.stop_reason = "kinetic_energy_ratio";
    s.max_speed_m_per_s = base + 1.0 / 7.0;
    s.water = filledWaterBalance( base + 10.0 );
    s.speed_percentile = 0.95;
    s.static_speed_m_per_s = 1.0e-3 / 3.0;
    s.speed_at_percentile_m_per_s = 2.0e-3 / 3.0;
    s.points_not_below_static_speed = 17 + static_cast<long>( base );
    s.allowed_points_not_below = 3;
    return s;
}

//! A loop state with no field at its default value: two finished stages,
//! a NaN, +-inf, 1e300, -0 and the smallest subnormal among the doubles.
inline mpm::StageLoopState filledLoopState()
{
    mpm::StageLoopState s;
    s.stage = 2;
    s.stage_started = true;
    s.progress.stage = "rain \"heavy\" \xc3\xb6\n";
    s.progress.stage_index = 2;
    s.progress.step = 987654321L;
    s.progress.stage_step = 4321;
    s.progress.time_s = 12.0 + 1.0 / 3.0;
    s.progress.stage_time_s = 2.0 / 3.0;
    s.progress.stage_duration_s = 1.0e300;
    s.progress.dt_s = 5.0e-324;
    s.progress.kinetic_energy_j = std::numeric_limits<double>::infinity();
    s.progress.active_points = 54321;
    s.stage_summary = filledStageSummary( 3.0, "rain" );
    s.stage_summary.ke_ratio = std::numeric_limits<double>::quiet_NaN();
    s.ke_max = 1.0e-300 / 3.0;
    s.below_since = -0.0;
    s.has_moved = true;
    s.static_since = 0.1 + 0.2;
    s.next_snapshot_s = 0.7;
    s.next_checkpoint_s = 12.5 + 1.0e-15;
    s.run.stages = { filledStageSummary( 1.0, "gravity" ),
                     filledStageSummary( 2.0, "settle" ) };
    s.run.stages[1].max_speed_m_per_s =
        -std::numeric_limits<double>::infinity();
    s.run.steps = 1L << 40;
    s.run.dt_min_s = 1.0e-6 / 3.0;
    s.run.dt_max_s = 1.0e300;
    s.run.interrupted = true;
    s.run.water = filledWaterBalance( 20.0 );
    return s;
}

} // namespace mpm_test

#endif // MPM_TEST_LOOP_STATE_HPP
