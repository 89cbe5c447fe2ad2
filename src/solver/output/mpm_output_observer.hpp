#ifndef MPM_OUTPUT_OBSERVER_HPP
#define MPM_OUTPUT_OBSERVER_HPP

#include <io/mpm_checkpoint.hpp>
#include <io/mpm_probe_recorder.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <solver/output/mpm_failure_verdict.hpp>
#include <solver/output/mpm_metrics.hpp>
#include <solver/output/mpm_progress.hpp>
#include <solver/output/mpm_run_observer.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Writes snapshots to HDF5/XDMF, checkpoints to
  `<out>/checkpoint.h5` and progress lines to stderr; stops the run on
  SIGINT/SIGTERM or after `stop_after_steps` steps.
*/
class OutputObserver : public RunObserver
{
  public:
    using clock = std::chrono::steady_clock;

    OutputObserver( SnapshotWriter& writer, ProgressPrinter& printer,
                    const std::string& checkpoint_path,
                    const double wall_before_s, const long stop_after_steps )
        : _writer( writer )
        , _printer( printer )
        , _checkpoint_path( checkpoint_path )
        , _wall_before_s( wall_before_s )
        , _stop_after_steps( stop_after_steps )
        , _start( clock::now() )
    {
    }
    void onStep( const RunProgress& progress ) override
    {
        ++_steps;
        _printer.update( progress );
    }
    void onSnapshot( const RunProgress& progress,
                     const HostSnapshot& snapshot ) override
    {
        writeSnapshot( _writer, progress, snapshot );
        pore_pressure.add( snapshot, progress.time_s );
        if ( verdict )
            verdict->add( progress, snapshot );
        last_snapshot = snapshot;
    }
    void onStageEnd( const RunProgress& progress,
                     const StageSummary& summary ) override
    {
        _printer.stageEnd( progress, summary );
        if ( verdict )
            verdict->endStage( progress, last_snapshot );
    }
    //! "<case file>: warning: <text>" on stderr.
    void onWarning( const std::string& text ) override
    {
        std::cerr << case_file << ": warning: " << text << "\n";
    }
    bool stopRequested() override
    {
        return interruptRequested() ||
               ( _stop_after_steps > 0 && _steps >= _stop_after_steps );
    }
    //! Writes the checkpoint; a failure is reported and the run goes on
    //! (the previous checkpoint stays valid).
    void onCheckpoint( Checkpoint& checkpoint ) override
    {
        checkpoint.snapshots = _writer.mark();
        checkpoint.wall_s = wallSeconds();
        try
        {
            const auto start = clock::now();
            writeCheckpoint( _checkpoint_path, checkpoint );
            const double write_s =
                std::chrono::duration<double>( clock::now() - start ).count();
            checkpoint_write_s_total += write_s;
            checkpoint_write_s_max =
                std::max( checkpoint_write_s_max, write_s );
            last_checkpoint_step = checkpoint.step;
            last_checkpoint_time_s = checkpoint.time_s;
            ++checkpoints_written;
        }
        catch ( const std::exception& error )
        {
            checkpoint_error = error.what();
            std::cerr << "rainslide: warning: checkpoint not written: "
                      << error.what() << "\n";
        }
    }
    double nextSampleTime() const override
    {
        return probes ? probes->nextTime() : 1.0e300;
    }
    void onSample( const RunProgress& progress,
                   const HostSnapshot& snapshot ) override
    {
        if ( probes )
            probes->record( progress, snapshot );
    }
    //! Wall time of the whole run: earlier sessions plus this one.
    double wallSeconds() const
    {
        return _wall_before_s +
               std::chrono::duration<double>( clock::now() - _start ).count();
    }

    std::string case_file; //!< names the case in warnings
    HostSnapshot last_snapshot;
    //! p_w extremes over this session's snapshots (two-phase).
    PorePressureExtremes pore_pressure;
    ProbeRecorder* probes = nullptr;   //!< tracked points, if the case has any
    FailureVerdict* verdict = nullptr; //!< whether the run failed
    int checkpoints_written = 0;
    double checkpoint_write_s_total = 0.0; //!< wall time writing them
    double checkpoint_write_s_max = 0.0;
    long last_checkpoint_step = -1;
    double last_checkpoint_time_s = 0.0;
    std::string checkpoint_error;

  private:
    SnapshotWriter& _writer;
    ProgressPrinter& _printer;
    std::string _checkpoint_path;
    double _wall_before_s;
    long _stop_after_steps;
    long _steps = 0;
    clock::time_point _start;
};

} // namespace mpm

#endif // MPM_OUTPUT_OBSERVER_HPP
