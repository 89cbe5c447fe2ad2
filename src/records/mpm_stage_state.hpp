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
  3. add its name to the NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE line of its
     struct in src/io/mpm_stage_state_json.hpp (StageLoopState, or
     StageSummary / RunProgress / RunSummary / physics::WaterBalance for
     theirs). The checkpoint file stores the loop state as that JSON; a
     field not listed there is silently lost on restart. Supported types:
     double, int, long, std::size_t, bool, std::string, std::vector and
     structs with a JSON definition there.
  4. a checkpoint written before the field existed lacks it and is refused
     ("loop state field '...' is missing"): the file format has no
     defaults. Raise the format version (format_name in
     src/io/mpm_checkpoint.cpp) so such a file is refused up front.
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

} // namespace mpm

#endif // MPM_STAGE_STATE_HPP
