#ifndef MPM_RUN_CASE_HPP
#define MPM_RUN_CASE_HPP

#include <io/mpm_case_config.hpp>
#include <io/mpm_json_output.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <solver/mpm_metrics.hpp>
#include <solver/mpm_progress.hpp>
#include <solver/mpm_run_stages.hpp>
#include <solver/mpm_simulation.hpp>

#include <Kokkos_Core.hpp>

#include <chrono>
#include <string>

namespace mpm
{
//! How the CLI asked for a run.
struct RunOptions
{
    std::string out_dir;
    std::string backend;
    int threads = 1;
    bool progress = true; //!< progress lines on stderr
};

//! Exit status of a run.
enum class RunStatus
{
    Completed,
    Interrupted,
    Failed
};

//---------------------------------------------------------------------------//
//! Writes snapshots to HDF5/XDMF and progress lines to stderr.
class OutputObserver : public RunObserver
{
  public:
    OutputObserver( SnapshotWriter& writer, ProgressPrinter& printer )
        : _writer( writer )
        , _printer( printer )
    {
    }
    void onStep( const RunProgress& progress ) override
    {
        _printer.update( progress );
    }
    void onSnapshot( const RunProgress& progress,
                     const HostSnapshot& snapshot ) override
    {
        writeSnapshot( _writer, progress, snapshot );
        last_snapshot = snapshot;
    }
    void onStageEnd( const RunProgress& progress,
                     const StageSummary& summary ) override
    {
        _printer.stageEnd( progress, summary );
    }
    bool stopRequested() override { return interruptRequested(); }

    HostSnapshot last_snapshot;

  private:
    SnapshotWriter& _writer;
    ProgressPrinter& _printer;
};

//---------------------------------------------------------------------------//
/*!
  \brief Runs a validated case on ExecSpace: snapshots to
  `<out>/particles.h5` + `.xdmf`, metrics to `<out>/metrics.json`.
  An unstable run stops with a diagnosis on stderr; what was written stays
  readable. Returns the run status.
*/
template <class ExecSpace>
RunStatus runCase( const CaseConfig& config, const RunOptions& options )
{
    const auto wall_start = std::chrono::steady_clock::now();
    Simulation<ExecSpace> sim( config );
    // Refuse a fixed time step above the stable limit before writing anything.
    chooseTimeStep( sim.solver, sim.waveSpeedLimit() );
    SnapshotWriter writer( options.out_dir );
    ProgressPrinter printer( config.name, sim.particles.size(),
                             options.progress );
    OutputObserver observer( writer, printer );
    installInterruptHandler();

    nlohmann::json metrics = {
        { "case", config.name },
        { "case_file", config.file },
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
        summary = runStages( sim, config, observer );
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
    const double wall_s = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - wall_start )
                              .count();
    writer.finalize();
    printer.finish();

    const long steps = sim.step;
    metrics["status"] = status == RunStatus::Completed     ? "completed"
                        : status == RunStatus::Interrupted ? "interrupted"
                                                           : "unstable";
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
    metrics["time_step"] = {
        { "rule", config.solver.dt_s > 0.0
                      ? "fixed dt_s, checked against the CFL limit"
                      : "automatic: courant_number x cell / (fastest wave "
                        "speed + point speed)" },
        { "limiting_wave",
          sim.twoPhase() ? "undrained mixture or pore-water wave (saturated "
                           "fluid stiffness, drag implicit)"
                         : "P wave of the skeleton" },
        { "courant_number", config.solver.courant_number },
        { "inertia_scaling", config.solver.inertia_scaling },
        { "final_cfl_limit_s", limit.dt_limit },
        { "final_max_wave_speed_m_per_s", limit.max_wave_speed } };
    metrics["stages"] = nlohmann::json::array();
    for ( const StageSummary& stage : summary.stages )
        metrics["stages"].push_back( stageMetrics( stage ) );
    if ( observer.last_snapshot.num_points > 0 )
        metrics["deformation"] =
            deformationMetrics( observer.last_snapshot, 0.05 );
    metrics["output"] = { { "hdf5", writer.h5Path() },
                          { "xdmf", writer.xdmfPath() },
                          { "snapshots", writer.snapshotCount() } };
    writeJsonAtomically( options.out_dir + "/metrics.json", metrics );
    printer.summary( metrics );
    return status;
}

} // namespace mpm

#endif // MPM_RUN_CASE_HPP
