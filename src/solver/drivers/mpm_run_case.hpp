#ifndef MPM_RUN_CASE_HPP
#define MPM_RUN_CASE_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>
#include <io/mpm_checkpoint_check.hpp>
#include <io/mpm_json_output.hpp>
#include <io/mpm_probe_recorder.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <setup/mpm_state_bounds.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_run_stages.hpp>
#include <solver/mpm_simulation.hpp>
#include <solver/output/mpm_metrics.hpp>
#include <solver/output/mpm_output_observer.hpp>
#include <solver/output/mpm_progress.hpp>
#include <solver/output/mpm_run_metrics.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm
{
//! How the CLI asked for a run.
struct RunOptions
{
    std::string out_dir;
    std::string backend;
    int threads = 1;
    bool progress = true; //!< progress lines on stderr
    //! Checkpoint to continue from; "" starts a new run.
    std::string restart_file;
    //! Overrides solver.checkpoint_interval_s when >= 0.
    double checkpoint_interval_s = -1.0;
    //! Stop as if interrupted after this many steps of this session (0:
    //! never); for splitting a run into sessions and for tests.
    long stop_after_steps = 0;
};

//! Exit status of a run.
enum class RunStatus
{
    Completed,
    Interrupted,
    Failed
};

//! Bad input found once the simulation is built, before its first step
//! (a fixed time step above the stable limit); nothing was written.
class RunRefused : public std::runtime_error
{
  public:
    explicit RunRefused( const std::string& message )
        : std::runtime_error( message )
    {
    }
};

//! A restart that cannot proceed (unreadable checkpoint, another case,
//! missing earlier snapshots); nothing was written.
class RestartError : public RunRefused
{
  public:
    explicit RestartError( const std::string& message )
        : RunRefused( message )
    {
    }
};

//! Why a run of `config` stops before its first step, or "": what runCase
//! refuses once the simulation is built (Simulation::nextStep: a fixed
//! solver.dt_s above the stable limit of the initial state).
template <class ExecSpace>
std::string firstStepRefusal( const CaseConfig& config )
{
    try
    {
        Simulation<ExecSpace> sim( config );
        sim.nextStep();
    }
    catch ( const std::exception& error )
    {
        return error.what();
    }
    return "";
}

//---------------------------------------------------------------------------//
/*!
  \brief Reads the checkpoint `restart_file` and refuses it (RestartError
  naming both files and what differs) if it was written for another case
  or is damaged. Does not change `sim`.
*/
template <class ExecSpace>
Checkpoint readMatchingCheckpoint( const Simulation<ExecSpace>& sim,
                                   const CaseConfig& config,
                                   const std::string& restart_file )
{
    Checkpoint checkpoint;
    try
    {
        checkpoint = readCheckpoint( restart_file );
    }
    catch ( const std::exception& error )
    {
        throw RestartError( "cannot read checkpoint '" + restart_file +
                            "': " + error.what() );
    }
    const std::string mismatch = checkpointMismatch(
        checkpoint, restart_file, checkpointIdentity( config, sim ) );
    if ( !mismatch.empty() )
        throw RestartError( mismatch );
    const std::string range =
        checkpointRangeError( checkpoint, config, stateBounds( config ) );
    if ( !range.empty() )
        throw RestartError( "checkpoint '" + restart_file +
                            "' is damaged: " + range );
    if ( checkpoint.identity.backend != ExecSpace::name() )
        std::cerr << "rainslide: note: the checkpoint was written on "
                  << checkpoint.identity.backend << ", this run uses "
                  << ExecSpace::name()
                  << ": the results continue the run but are not bitwise "
                     "those of an uninterrupted run\n";
    return checkpoint;
}

//---------------------------------------------------------------------------//
/*!
  \brief Reads the checkpoint `options.restart_file` (readMatchingCheckpoint)
  and puts `sim` into its state. The snapshots written before it are found
  next to it (see SnapshotWriter::findSeries).
*/
template <class ExecSpace>
Checkpoint resumeFromCheckpoint( Simulation<ExecSpace>& sim,
                                 const CaseConfig& config,
                                 const RunOptions& options,
                                 std::string& earlier_snapshots )
{
    Checkpoint checkpoint =
        readMatchingCheckpoint( sim, config, options.restart_file );
    const auto folder =
        std::filesystem::path( options.restart_file ).parent_path();
    const std::string stem = ( folder / "particles.h5" ).string();
    try
    {
        earlier_snapshots = SnapshotWriter::findSeries(
            { stem + ".partial", stem }, checkpoint.snapshots );
    }
    catch ( const std::exception& error )
    {
        throw RestartError( "cannot restart from checkpoint '" +
                            options.restart_file + "': " + error.what() );
    }
    restoreCheckpoint( sim, config, checkpoint );
    return checkpoint;
}

//---------------------------------------------------------------------------//
/*!
  \brief Runs a validated case on ExecSpace: snapshots to
  `<out>/particles.h5` + `.xdmf`, metrics to `<out>/metrics.json`,
  checkpoints to `<out>/checkpoint.h5` (every
  solver.checkpoint_interval_s and on SIGINT/SIGTERM).
  With options.restart_file the run continues that checkpoint: the
  particle file holds the snapshots before it and those after it, the
  metrics cover the whole run (steps, simulated time, wall time summed
  over the sessions).
  An unstable run stops with a diagnosis on stderr; what was written stays
  readable. Returns the run status.
*/
template <class ExecSpace>
RunStatus runCase( const CaseConfig& case_config, const RunOptions& options )
{
    installInterruptHandler();
    const auto wall_start = std::chrono::steady_clock::now();
    CaseConfig config = case_config;
    if ( options.checkpoint_interval_s >= 0.0 )
        config.solver.checkpoint_interval_s = options.checkpoint_interval_s;
    Simulation<ExecSpace> sim( config );
    // Probe points are picked from the initial state, also on a restart.
    ProbeRecorder probes( config, hostSnapshot( sim ), options.out_dir );
    std::optional<Checkpoint> resumed;
    std::string earlier_snapshots;
    if ( !options.restart_file.empty() )
        resumed =
            resumeFromCheckpoint( sim, config, options, earlier_snapshots );
    // Refuse a fixed time step above the stable limit before writing anything.
    try
    {
        sim.nextStep();
    }
    catch ( const SimulationError& error )
    {
        throw RunRefused( error.what() );
    }
    // Interrupted while it was set up: nothing written yet.
    if ( interruptRequested() )
    {
        std::cerr << "rainslide: interrupted before the first step; nothing "
                     "was written\n";
        return RunStatus::Interrupted;
    }
    // Accepted: an old metrics.json must not survive a run that then fails
    // to write one (a refused run leaves the folder as it was).
    std::filesystem::remove( options.out_dir + "/metrics.json" );
    // The probe rows before the particles: a damaged probes.csv must not
    // cut particles.h5 to the kept snapshots.
    try
    {
        probes.open( resumed ? resumed->time_s : -1.0 );
    }
    catch ( const std::exception& error )
    {
        if ( !resumed )
            throw;
        throw RestartError( "cannot restart from checkpoint '" +
                            options.restart_file + "': " + error.what() );
    }
    SnapshotWriter writer( options.out_dir, "particles", earlier_snapshots,
                           resumed ? resumed->snapshots
                                   : SnapshotSeriesMark() );
    ProgressPrinter printer( config.name, sim.particles.size(),
                             options.progress );
    const std::string checkpoint_file = checkpointPath( options.out_dir );
    OutputObserver observer( writer, printer, checkpoint_file,
                             resumed ? resumed->wall_s : 0.0,
                             options.stop_after_steps );
    observer.probes = &probes;
    observer.case_file = config.file;
    std::vector<bool> dynamic_stages;
    for ( const StageConfig& stage : config.stages )
        dynamic_stages.push_back( stage.type == StageType::Dynamic );
    FailureVerdict verdict( dynamic_stages );
    observer.verdict = &verdict;

    nlohmann::json metrics = {
        { "case", config.name },
        { "case_file", config.file },
        { "overrides", config.overrides },
        { "backend", options.backend },
        { "threads", ExecSpace::concurrency() },
        { "n_particles", sim.particles.size() },
        { "n_cells", config.grid.cells[0] * config.grid.cells[1] },
        { "cell_size_m", config.grid.cell_size_m },
        { "output_dir", options.out_dir } };

    RunStatus status = RunStatus::Completed;
    RunSummary summary;
    try
    {
        summary = runStages( sim, config, observer,
                             resumed ? resumed->loop : StageLoopState() );
        if ( summary.interrupted )
            status = RunStatus::Interrupted;
    }
    catch ( const SimulationError& error )
    {
        status = RunStatus::Failed;
        metrics["error"] = error.what();
        printer.finish();
        std::cerr << "rainslide: error: the run stopped\n"
                  << error.what() << "\n";
        // Keep the state at the failure for inspection.
        RunProgress at_failure;
        at_failure.stage = "failure";
        at_failure.step = sim.step;
        at_failure.time_s = sim.time;
        writeSnapshot( writer, at_failure, hostSnapshot( sim ) );
    }
    const double session_wall_s =
        std::chrono::duration<double>( std::chrono::steady_clock::now() -
                                       wall_start )
            .count();
    const double wall_s = ( resumed ? resumed->wall_s : 0.0 ) + session_wall_s;
    writer.finalize();
    probes.finish();
    if ( probes.failed() )
    {
        const std::string error = "a write to " + probes.path() +
                                  ".partial failed (disk full?); it was "
                                  "not renamed to " +
                                  probes.path();
        metrics["probes_error"] = error;
        std::cerr << "rainslide: error: " << error << "\n";
        if ( status == RunStatus::Completed )
            status = RunStatus::Failed;
    }
    printer.finish();

    const long steps = sim.step;
    metrics["status"] = status == RunStatus::Completed     ? "completed"
                        : status == RunStatus::Interrupted ? "interrupted"
                                                           : "unstable";
    // A completed run whose quasi-static stage ran out of time unconverged.
    std::vector<std::string> unconverged;
    for ( const StageSummary& stage : summary.stages )
        if ( !stage.converged && stage.stop_reason != "interrupted" )
            unconverged.push_back( stage.name );
    if ( status == RunStatus::Completed && !unconverged.empty() )
    {
        metrics["status"] = "unconverged";
        metrics["unconverged_stages"] = unconverged;
        std::cerr << "rainslide: warning: quasi-static stage(s) did not "
                     "converge within duration_s: "
                  << unconverged.front()
                  << ( unconverged.size() > 1 ? " and others" : "" )
                  << " (metrics.json: status \"unconverged\")\n";
    }
    metrics["steps"] = steps;
    metrics["wall_s"] = wall_s;
    metrics["simulated_time_s"] = sim.time;
    metrics["mp_updates_per_s"] =
        wall_s > 0.0 ? double( steps ) * sim.numActivePoints() / wall_s : 0.0;
    metrics["dt_s"] = summary.dt_max_s;
    metrics["dt_min_s"] = summary.steps > 0 ? summary.dt_min_s : 0.0;
    metrics["removed_points"] = sim.num_removed;
    // Which limit set the step.
    const WaveSpeedLimit limit = sim.waveSpeedLimit();
    metrics["time_step"] = timeStepMetrics(
        config.solver,
        { sim.schemeName(), sim.stepRule(), sim.limitingWave(), limit.dt_limit,
          limit.max_wave_speed, sim.stepsRetaken() } );
    if ( const PressureSolveStats* solves = sim.pressureSolveStats() )
        metrics["pressure_solve"] =
            pressureSolveMetrics( config.solver, *solves );
    if ( const RelaxationStats* relaxations = sim.relaxationStats() )
        metrics["relaxation"] =
            relaxationMetrics( config.solver, *relaxations );
    if ( const AutoStats* automatic = sim.autoStats() )
        metrics["auto"] = autoMetrics( config.solver, *automatic );
    metrics["stages"] = nlohmann::json::array();
    for ( const StageSummary& stage : summary.stages )
        metrics["stages"].push_back( stageMetrics( stage, sim.twoPhase() ) );
    if ( sim.twoPhase() && !summary.stages.empty() )
        metrics["water_balance"] = waterBalanceMetrics( summary.water );
    observer.pore_pressure.write( metrics );
    if ( observer.last_snapshot.num_points > 0 )
        metrics["deformation"] =
            deformationMetrics( observer.last_snapshot, 0.05 );
    metrics["verdict"] = verdict.json( config.file );
    metrics["output"] = { { "hdf5", writer.h5Path() },
                          { "xdmf", writer.xdmfPath() },
                          { "snapshots", writer.snapshotCount() } };
    metrics["checkpoint"] = {
        { "file", checkpoint_file },
        { "interval_s", config.solver.checkpoint_interval_s },
        { "written_this_session", observer.checkpoints_written },
        { "write_s_total", observer.checkpoint_write_s_total },
        { "write_s_max", observer.checkpoint_write_s_max },
        { "last_step", observer.last_checkpoint_step },
        { "last_time_s", observer.last_checkpoint_time_s } };
    if ( !observer.checkpoint_error.empty() )
        metrics["checkpoint"]["error"] = observer.checkpoint_error;
    if ( resumed )
        metrics["restart"] = { { "from", options.restart_file },
                               { "step", resumed->step },
                               { "time_s", resumed->time_s },
                               { "wall_s_before", resumed->wall_s },
                               { "wall_s_this_session", session_wall_s },
                               { "snapshots_kept", resumed->snapshots.count } };
    writeJsonAtomically( options.out_dir + "/metrics.json", metrics );
    printer.summary( metrics );
    std::cout << "[" << config.name
              << "] verdict: " << verdict.line( config.file ) << "\n";
    if ( status == RunStatus::Interrupted )
        printResumeHint(
            config.file,
            "--backend " + options.backend +
                ( options.backend == "openmp"
                      ? " --threads " +
                            std::to_string( ExecSpace::concurrency() )
                      : "" ) +
                " --out " + options.out_dir,
            checkpoint_file, observer.last_checkpoint_step,
            observer.last_checkpoint_time_s );
    return status;
}

} // namespace mpm

#endif // MPM_RUN_CASE_HPP
