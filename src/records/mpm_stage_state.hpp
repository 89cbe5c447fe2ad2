#ifndef MPM_STAGE_STATE_HPP
#define MPM_STAGE_STATE_HPP

#include <records/mpm_run_records.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace mpm
{
//! Outcome of runStages.
struct RunSummary
{
    std::vector<StageSummary> stages;
    long steps = 0;
    //! Smallest and largest step the stability rule chose (not the steps
    //! cut short to land on a snapshot time or the stage end); 1e300 and 0
    //! before the first step.
    double dt_min_s = 1.0e300;
    double dt_max_s = 0.0;
    bool interrupted = false; //!< stopped by RunObserver::stopRequested
    //! Two-phase: the water balance of the finished stages.
    physics::WaterBalance water;
};

//---------------------------------------------------------------------------//
/*!
  \brief Everything the stage loop of runStages carries from one step to
  the next. runStages starts from a StageLoopState (a fresh one, or the one
  of a checkpoint) and a checkpoint saves it, so a restarted run continues
  the loop exactly where it stopped.

  Adding a field (e.g. for a new stop criterion or output):
  1. add it here with its initial value (the value of a fresh run);
  2. if it is per stage, reset it in beginStage();
  3. add one line for it to visitStageLoopState() below (or to
     visitStageSummary() / visitRunSummary() for those structs). The
     checkpoint file (src/io/mpm_checkpoint.cpp) writes and reads every
     visited field by name; a field it does not visit is silently lost on
     restart. Supported types: double, int, long, std::size_t, bool,
     std::string, std::vector<StageSummary>.
  4. a checkpoint written before the field existed lacks it and is refused
     ("missing loop field"): the file format has no defaults.
  Derived values (the stage's settings, its snapshot schedule) are not
  state: runStages recomputes them from the case.
*/
struct StageLoopState
{
    std::size_t stage = 0;      //!< index of the current stage
    bool stage_started = false; //!< the stage's applyStage has run
    RunProgress progress;       //!< step counters and times
    StageSummary stage_summary; //!< the current stage so far
    double ke_max = 0.0;        //!< largest kinetic energy of the stage, J
    //! Stage time since which E_kin / ke_max is below the tolerance, or -1.
    double below_since = -1.0;
    //! Static stop: a point has moved farther than the slide displacement.
    bool has_moved = false;
    //! Static stop: stage time since which the speed statistic is below
    //! the static speed (after moving), or -1.
    double static_since = -1.0;
    double next_snapshot_s = 0.0;   //!< stage time of the next snapshot
    double next_checkpoint_s = 0.0; //!< run time of the next checkpoint
    RunSummary run;                 //!< finished stages and totals

    //! Resets the per-stage fields at the start of stage `index`.
    void beginStage( const std::size_t index, const std::string& name,
                     const double duration_s, const bool quasi_static,
                     const double first_snapshot_s )
    {
        stage = index;
        stage_started = true;
        progress.stage = name;
        progress.stage_index = static_cast<int>( index );
        progress.stage_duration_s = duration_s;
        progress.stage_step = 0;
        progress.stage_time_s = 0.0;
        stage_summary = StageSummary();
        stage_summary.name = name;
        stage_summary.type = quasi_static ? "quasi_static" : "dynamic";
        stage_summary.dt_min_s = 1.0e300;
        stage_summary.converged = !quasi_static;
        ke_max = 0.0;
        below_since = -1.0;
        has_moved = false;
        static_since = -1.0;
        next_snapshot_s = first_snapshot_s;
    }
};

//---------------------------------------------------------------------------//
//! Calls f(name, field) for every field of a physics::WaterBalance.
template <class Balance, class F>
void visitWaterBalance( Balance& w, F&& f )
{
    f( "stored_start_m3_per_m", w.stored_start );
    f( "stored_end_m3_per_m", w.stored_end );
    f( "carried_off_start_m3_per_m", w.carried_off_start );
    f( "carried_off_end_m3_per_m", w.carried_off_end );
    f( "point_inflow_m3_per_m", w.point_inflow );
    f( "runoff_m3_per_m", w.runoff );
    f( "prescribed_pressure_m3_per_m", w.prescribed );
    f( "flow_in_m3_per_m", w.flow_in );
}

//! Calls f(name, field) for every field of a StageSummary.
template <class Summary, class F>
void visitStageSummary( Summary& s, F&& f )
{
    f( "name", s.name );
    f( "type", s.type );
    f( "steps", s.steps );
    f( "duration_s", s.duration_s );
    f( "dt_min_s", s.dt_min_s );
    f( "dt_max_s", s.dt_max_s );
    f( "ke_ratio", s.ke_ratio );
    f( "converged", s.converged );
    f( "stop_reason", s.stop_reason );
    f( "max_speed_m_per_s", s.max_speed_m_per_s );
    visitWaterBalance( s.water, [&]( const std::string& name, auto& value )
                       { f( "water." + name, value ); } );
    f( "speed_percentile", s.speed_percentile );
    f( "static_speed_m_per_s", s.static_speed_m_per_s );
    f( "speed_at_percentile_m_per_s", s.speed_at_percentile_m_per_s );
    f( "points_not_below_static_speed", s.points_not_below_static_speed );
    f( "allowed_points_not_below", s.allowed_points_not_below );
}

//! Calls f(name, field) for every field of a RunProgress.
template <class Progress, class F>
void visitRunProgress( Progress& p, F&& f )
{
    f( "stage", p.stage );
    f( "stage_index", p.stage_index );
    f( "step", p.step );
    f( "stage_step", p.stage_step );
    f( "time_s", p.time_s );
    f( "stage_time_s", p.stage_time_s );
    f( "stage_duration_s", p.stage_duration_s );
    f( "dt_s", p.dt_s );
    f( "kinetic_energy_j", p.kinetic_energy_j );
    f( "active_points", p.active_points );
}

//! Calls f(name, field) for every field of a RunSummary.
template <class Summary, class F>
void visitRunSummary( Summary& s, F&& f )
{
    f( "stages", s.stages );
    f( "steps", s.steps );
    f( "dt_min_s", s.dt_min_s );
    f( "dt_max_s", s.dt_max_s );
    f( "interrupted", s.interrupted );
    visitWaterBalance( s.water, [&]( const std::string& name, auto& value )
                       { f( "water." + name, value ); } );
}

/*!
  \brief Calls f(name, field) for every field of the loop state, nested
  structs with dotted names ("progress.step", "run.steps"). State may be
  const (writing) or not (reading).
*/
template <class State, class F>
void visitStageLoopState( State& s, F&& f )
{
    f( "stage", s.stage );
    f( "stage_started", s.stage_started );
    visitRunProgress( s.progress, [&]( const std::string& name, auto& value )
                      { f( "progress." + name, value ); } );
    visitStageSummary( s.stage_summary,
                       [&]( const std::string& name, auto& value )
                       { f( "stage_summary." + name, value ); } );
    f( "ke_max", s.ke_max );
    f( "below_since", s.below_since );
    f( "has_moved", s.has_moved );
    f( "static_since", s.static_since );
    f( "next_snapshot_s", s.next_snapshot_s );
    f( "next_checkpoint_s", s.next_checkpoint_s );
    visitRunSummary( s.run, [&]( const std::string& name, auto& value )
                     { f( "run." + name, value ); } );
}

} // namespace mpm

#endif // MPM_STAGE_STATE_HPP
