#ifndef MPM_FOS_RUN_HPP
#define MPM_FOS_RUN_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_json_output.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <solver/drivers/mpm_fos_criterion.hpp>
#include <solver/drivers/mpm_fos_search.hpp>
#include <solver/drivers/mpm_fos_trial.hpp>
#include <solver/drivers/mpm_run_case.hpp>
#include <solver/drivers/mpm_run_stages.hpp>
#include <solver/output/mpm_progress.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace mpm
{
//! How `rainslide fos` was asked to search.
struct FosOptions
{
    FosSearchSettings search;
    FosCriterion criterion;
    //! > 0: a history, a search every this many seconds of the last stage
    //! (runFosHistory).
    double every_s = 0.0;
};

//! What a factor-of-safety search found, with every trial.
struct FosReport
{
    FosSearchResult search;
    std::vector<FosTrialRecord> trials;
    //! The points at the end of the smallest failing trial (if any).
    std::optional<HostSnapshot> mechanism;
    double mechanism_factor = 0.0;
    double trial_duration_s = 0.0;
    //! Where the searched state came from: "stages" or the checkpoint's
    //! path; its simulated time and the stage whose conditions the trials
    //! keep.
    std::string state_from = "stages";
    double state_time_s = 0.0;
    long state_step = 0;
    std::string trial_stage;
};

//---------------------------------------------------------------------------//
/*!
  \brief Searches the factor of safety of the state `sim` holds now, with
  the trials in stage `base_stage`'s conditions (FosTrialRunner,
  searchFactorOfSafety). One line per trial on stderr unless `quiet`.
*/
template <class ExecSpace>
FosReport searchFos( Simulation<ExecSpace>& sim, const CaseConfig& config,
                     const std::size_t base_stage, const FosOptions& options,
                     const bool quiet = true )
{
    FosTrialRunner<ExecSpace> runner( sim, config, base_stage,
                                      options.criterion );
    FosReport report;
    report.trial_duration_s = runner.duration();
    report.state_time_s = sim.time;
    report.state_step = sim.step;
    report.trial_stage = config.stages.at( base_stage ).name;
    const auto trial = [&]( const double factor )
    {
        HostSnapshot end_state;
        FosTrialRecord record = runner.run( factor, &end_state );
        if ( record.fails &&
             ( !report.mechanism || factor < report.mechanism_factor ) )
        {
            report.mechanism = std::move( end_state );
            report.mechanism_factor = factor;
        }
        if ( !quiet )
            std::fprintf( stderr,
                          "fos: F = %.4f %s (%s): u_max %.4g m, %.3g m in "
                          "the last quarter, E_kin ratio %.3g, %ld "
                          "steps, %.1f s\n",
                          factor, record.fails ? "fails" : "stable",
                          record.reason.c_str(), record.u_max_m,
                          record.last_quarter_m, record.ke_ratio, record.steps,
                          record.wall_s );
        report.trials.push_back( record );
        return FosVerdict{ record.fails };
    };
    report.search = searchFactorOfSafety( options.search, trial );
    return report;
}

//---------------------------------------------------------------------------//
//! The fos.json document of a search.
inline nlohmann::json fosJson( const CaseConfig& config,
                               const FosOptions& options,
                               const FosReport& report, const double wall_s )
{
    const FosSearchResult& s = report.search;
    nlohmann::json j = {
        { "case", config.name },
        { "case_file", config.file },
        { "overrides", config.overrides },
        { "status", s.status },
        { "factor_of_safety",
          s.found ? nlohmann::json( s.factor ) : nlohmann::json() },
        { "bracket", { s.stable, s.failing } },
        { "tolerance", options.search.tolerance },
        { "state",
          { { "from", report.state_from },
            { "time_s", report.state_time_s },
            { "stage", report.trial_stage } } },
        { "criterion",
          { { "text", describeCriterion( options.criterion ) },
            { "damping", options.criterion.damping },
            { "periods", options.criterion.periods },
            { "trial_duration_s", report.trial_duration_s },
            { "displacement_limit_m", options.criterion.displacement_limit_m },
            { "creep_limit_m", options.criterion.creep_limit_m },
            { "energy_ratio", options.criterion.energy_ratio } } },
        { "strength_reduction",
          "c_peak, c_residual, the softening modulus and the tensile "
          "strength divided by F; tan(phi) and tan(psi) divided by F; pore "
          "pressures held at their values at the start of every trial, the "
          "water locked to the skeleton (permeability 0)" },
        { "wall_s", wall_s } };
    j["trials"] = nlohmann::json::array();
    for ( const FosTrialRecord& r : report.trials )
        j["trials"].push_back( trialJson( r ) );
    if ( report.mechanism )
        j["mechanism"] = { { "factor", report.mechanism_factor },
                           { "hdf5", "mechanism.h5" },
                           { "xdmf", "mechanism.xdmf" } };
    return j;
}

//---------------------------------------------------------------------------//
//! Creates `out_dir` and removes a search's results from it.
inline void removeFosResult( const std::string& out_dir )
{
    std::filesystem::create_directories( out_dir );
    for ( const char* name :
          { "/fos.json", "/mechanism.h5", "/mechanism.xdmf" } )
        std::filesystem::remove( out_dir + name );
}

//---------------------------------------------------------------------------//
/*!
  \brief Writes a search's results into `out_dir`: the failure mechanism
  (`mechanism.h5` + `.xdmf`, if a trial failed) and then `fos.json`
  (atomically, last). Earlier results there are removed first, so no
  earlier result survives a search that writes none.
*/
inline void writeFosResult( const std::string& out_dir,
                            const CaseConfig& config, const FosOptions& options,
                            const FosReport& report, const double wall_s )
{
    removeFosResult( out_dir );
    if ( report.mechanism )
    {
        SnapshotWriter writer( out_dir, "mechanism" );
        RunProgress at;
        at.stage = "fos_trial";
        at.step = report.state_step;
        at.time_s = report.trial_duration_s;
        writeSnapshot( writer, at, *report.mechanism );
        writer.finalize();
    }
    writeJsonAtomically( out_dir + "/fos.json",
                         fosJson( config, options, report, wall_s ) );
}

//---------------------------------------------------------------------------//
//! Progress lines and Ctrl-C for the stages run before a search.
class FosStageObserver : public RunObserver
{
  public:
    explicit FosStageObserver( ProgressPrinter& printer )
        : _printer( printer )
    {
    }
    void onStep( const RunProgress& progress ) override
    {
        _printer.update( progress );
    }
    void onStageEnd( const RunProgress& progress,
                     const StageSummary& summary ) override
    {
        _printer.stageEnd( progress, summary );
    }
    bool stopRequested() override { return interruptRequested(); }

  private:
    ProgressPrinter& _printer;
};

//---------------------------------------------------------------------------//
/*!
  \brief `rainslide fos`: runs the case's stages (or, with
  run.restart_file, takes the checkpoint's state), then searches the
  factor of safety of that state in the conditions of the last stage (of
  the checkpoint's stage). Writes `<out>/fos.json` (atomically, last) and,
  if a trial failed, `<out>/mechanism.h5` + `.xdmf` with the points at the
  end of the smallest failing F. Returns 0 if the factor was found, 1 if
  not (or a stage run stopped), 130 if interrupted.
*/
template <class ExecSpace>
int runFos( const CaseConfig& config, const RunOptions& run,
            const FosOptions& options )
{
    const auto wall_start = std::chrono::steady_clock::now();
    Simulation<ExecSpace> sim( config );
    std::size_t base_stage = config.stages.size() - 1;
    if ( !run.restart_file.empty() )
    {
        const Checkpoint checkpoint =
            readMatchingCheckpoint( sim, config, run.restart_file );
        restoreCheckpoint( sim, config, checkpoint );
        base_stage = checkpoint.loop.stage;
    }
    chooseTimeStep( sim.solver, sim.waveSpeedLimit() );
    // Accepted: no earlier result may survive a search that writes none.
    removeFosResult( run.out_dir );
    installInterruptHandler();
    if ( run.restart_file.empty() )
    {
        ProgressPrinter printer( config.name, sim.particles.size(),
                                 run.progress );
        FosStageObserver observer( printer );
        try
        {
            const RunSummary summary = runStages( sim, config, observer );
            printer.finish();
            if ( summary.interrupted )
                return 130;
            for ( const StageSummary& stage : summary.stages )
                if ( !stage.converged &&
                     config.stages[&stage - summary.stages.data()].type ==
                         StageType::QuasiStatic )
                    std::cerr << "rainslide: warning: quasi-static stage '"
                              << stage.name
                              << "' did not converge within duration_s; the "
                                 "search starts from its last state\n";
        }
        catch ( const SimulationError& error )
        {
            printer.finish();
            std::cerr << "rainslide: error: a stage run stopped before the "
                         "search\n"
                      << error.what() << "\n";
            return 1;
        }
    }
    FosReport report;
    try
    {
        report = searchFos( sim, config, base_stage, options, !run.progress );
    }
    catch ( const FosInterrupted& stop )
    {
        std::cerr << "rainslide: " << stop.what() << "; no fos.json written\n";
        return 130;
    }
    if ( !run.restart_file.empty() )
        report.state_from = run.restart_file;
    const double wall_s = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - wall_start )
                              .count();
    writeFosResult( run.out_dir, config, options, report, wall_s );
    const FosSearchResult& s = report.search;
    if ( s.found )
        std::cout << "factor of safety " << s.factor << " (stable at "
                  << s.stable << ", fails at " << s.failing << "), "
                  << report.trials.size() << " trials, " << wall_s << " s\n";
    else
        std::cerr << "rainslide: error: no factor of safety: " << s.status
                  << " (" << report.trials.size() << " trials; " << run.out_dir
                  << "/fos.json)\n";
    return s.found ? 0 : 1;
}

} // namespace mpm

#endif // MPM_FOS_RUN_HPP
