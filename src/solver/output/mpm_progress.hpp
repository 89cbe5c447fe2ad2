#ifndef MPM_PROGRESS_HPP
#define MPM_PROGRESS_HPP

#include <io/mpm_snapshot_writer.hpp>
#include <solver/output/mpm_run_observer.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Progress lines on stderr while running: stage, step, simulated
  time, wall time, ETA of the stage, material-point updates per second.
*/
class ProgressPrinter
{
  public:
    ProgressPrinter( const std::string& case_name, int num_points, bool enabled,
                     double interval_s = 2.0 );
    //! Prints a line if `interval_s` of wall time passed since the last.
    void update( const RunProgress& progress );
    void stageEnd( const RunProgress& progress, const StageSummary& summary );
    //! Ends the progress output (idempotent).
    void finish();
    //! The end-of-run summary, from the metrics.
    void summary( const nlohmann::json& metrics ) const;

  private:
    using clock = std::chrono::steady_clock;
    std::string _case_name;
    int _num_points;
    bool _enabled;
    double _interval_s;
    clock::time_point _start;
    clock::time_point _last_print;
    clock::time_point _stage_start;
    // Where the rate and ETA of the stage are measured from: the stage
    // start, or the first step of a restarted run.
    bool _has_baseline = false;
    long _stage_start_step = 0;
    double _stage_start_time_s = 0.0;
};

//! Appends one snapshot of every particle field to the writer.
void writeSnapshot( SnapshotWriter& writer, const RunProgress& progress,
                    const HostSnapshot& snapshot );

/*!
  \brief After an interrupted run: where the checkpoint is and the command
  that continues the run with the options `run_options` (or, if
  checkpoint_step < 0, that none was written).
*/
void printResumeHint( const std::string& case_file,
                      const std::string& run_options,
                      const std::string& checkpoint_file, long checkpoint_step,
                      double checkpoint_time_s );

/*!
  \brief From now on SIGINT/SIGTERM set a flag (the run stops cleanly
  between steps, after writing a checkpoint; before the first step, nothing
  is written). A signal the process inherited as ignored (a background job)
  stays ignored; installing again keeps a flag already set.
*/
void installInterruptHandler();
bool interruptRequested();

} // namespace mpm

#endif // MPM_PROGRESS_HPP
