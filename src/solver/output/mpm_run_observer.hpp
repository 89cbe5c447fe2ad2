#ifndef MPM_RUN_OBSERVER_HPP
#define MPM_RUN_OBSERVER_HPP

#include <records/mpm_run_records.hpp>

#include <string>
#include <vector>

namespace mpm
{
struct Checkpoint; // io/mpm_checkpoint.hpp

//! Receives progress, snapshots and stage ends of a run.
class RunObserver
{
  public:
    virtual ~RunObserver() = default;
    //! Called after every step.
    virtual void onStep( const RunProgress& ) {}
    //! Called when the case asks for a snapshot.
    virtual void onSnapshot( const RunProgress&, const HostSnapshot& ) {}
    //! Run time at which the observer wants its next sample (e.g. probe
    //! records); onSample is called after the first step that reaches it.
    virtual double nextSampleTime() const { return 1.0e300; }
    //! Called with the state at a sample time.
    virtual void onSample( const RunProgress&, const HostSnapshot& ) {}
    //! Called at the end of each stage.
    virtual void onStageEnd( const RunProgress&, const StageSummary& ) {}
    //! Polled between steps; returning true stops the run cleanly (after
    //! onCheckpoint with the state at the stop).
    virtual bool stopRequested() { return false; }
    //! Called with the whole run state when a checkpoint is due (every
    //! solver.checkpoint_interval_s and at a stop). Writing it is up to the
    //! observer, which completes the outputs' part first (snapshots, wall_s).
    virtual void onCheckpoint( Checkpoint& ) {}
    //! Called with a warning about the case ("key '...': ..."), e.g. a
    //! point selection that picks no point at its stage's start.
    virtual void onWarning( const std::string& ) {}
};

} // namespace mpm

#endif // MPM_RUN_OBSERVER_HPP
