#ifndef MPM_FOS_HISTORY_HPP
#define MPM_FOS_HISTORY_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>
#include <io/mpm_json_output.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <solver/drivers/mpm_checkpoint_state.hpp>
#include <solver/drivers/mpm_fos_run.hpp>
#include <solver/drivers/mpm_run_stages.hpp>
#include <solver/mpm_simulation.hpp>
#include <solver/output/mpm_progress.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Stops the stages' run at the times of a factor-of-safety history:
  the start of the last stage and every `every_s` of its time after that.
  The state at a stop arrives through onCheckpoint (taken before a step,
  the point a run resumes at exactly). Progress lines and Ctrl-C as in a
  run.
*/
class FosHistoryObserver : public RunObserver
{
  public:
    FosHistoryObserver( ProgressPrinter& printer, const int last_stage,
                        const double every_s )
        : _printer( printer )
        , _last_stage( last_stage )
        , _every_s( every_s )
        , _due( last_stage == 0 ) // a one-stage case: its start
    {
    }
    void onStep( const RunProgress& progress ) override
    {
        _printer.update( progress );
        _last = progress;
        if ( dueAt( progress ) )
            _due = true;
    }
    //! Whether a search is due in the state after `progress`'s step (steps
    //! land on snapshot times; round-off of the summed steps).
    bool dueAt( const RunProgress& progress ) const
    {
        return progress.stage_index == _last_stage &&
               progress.stage_time_s >= _next_s * ( 1.0 - 1.0e-9 );
    }
    //! The progress after the last step.
    const RunProgress& lastProgress() const { return _last; }
    void onStageEnd( const RunProgress& progress,
                     const StageSummary& summary ) override
    {
        if ( _due )
            return; // a stop for a search, not the stage's end
        _printer.stageEnd( progress, summary );
        if ( progress.stage_index + 1 == _last_stage )
            _due = true; // the first search: the last stage's start
    }
    bool stopRequested() override { return interruptRequested() || _due; }
    void onCheckpoint( Checkpoint& checkpoint ) override
    {
        if ( _due && !interruptRequested() )
            _state = std::move( checkpoint );
    }
    //! The state at a search time, once (empty if the run did not stop
    //! for a search).
    std::optional<Checkpoint> takeState()
    {
        std::optional<Checkpoint> state = std::move( _state );
        _state.reset();
        if ( state )
        {
            _due = false;
            _next_s += _every_s;
        }
        return state;
    }

  private:
    ProgressPrinter& _printer;
    int _last_stage;
    double _every_s;
    double _next_s = 0.0;
    bool _due;
    RunProgress _last;
    std::optional<Checkpoint> _state;
};

//---------------------------------------------------------------------------//
//! `config` with the search times (multiples of every_s) added to its last
//! stage's snapshot times, so that the run's steps land on them.
inline CaseConfig withSearchTimes( CaseConfig config, const double every_s )
{
    StageConfig& last = config.stages.back();
    std::vector<double>& times = last.snapshot_times_s;
    for ( double t = every_s; t < last.duration_s; t += every_s )
        times.push_back( t );
    std::sort( times.begin(), times.end() );
    return config;
}

//---------------------------------------------------------------------------//
//! One row of fos_history.json.
inline nlohmann::json fosHistoryRow( const RunProgress& at,
                                     const FosReport& report,
                                     const std::string& folder,
                                     const double wall_s )
{
    const FosSearchResult& s = report.search;
    return { { "stage_time_s", at.stage_time_s },
             { "time_s", at.time_s },
             { "status", s.status },
             { "factor_of_safety",
               s.found ? nlohmann::json( s.factor ) : nlohmann::json() },
             { "bracket", { s.stable, s.failing } },
             { "trials", report.trials.size() },
             { "folder", folder },
             { "wall_s", wall_s } };
}

//---------------------------------------------------------------------------//
/*!
  \brief `rainslide fos --every-s S` (options.every_s): runs the case's stages
  and searches the factor of safety at the start of the last stage and every S
  seconds of it (e.g. through a rainfall), each on a copy of the run's state
  then (restored from a checkpoint taken there), so the run itself continues
  unchanged. Writes, in `run.out_dir`, one folder per search
  (`t_<stage time>/fos.json` and its mechanism), the searched states
  (`states.h5` + `.xdmf`, one snapshot each) and `fos_history.json`
  (rewritten atomically after every search). Returns 0 when the stage
  ended (by its duration or its static stop), 1 if the run stopped with
  an error, 130 if interrupted.
*/
template <class ExecSpace>
int runFosHistory( const CaseConfig& case_config, const RunOptions& run,
                   const FosOptions& options )
{
    const CaseConfig config = withSearchTimes( case_config, options.every_s );
    const auto wall_start = std::chrono::steady_clock::now();
    Simulation<ExecSpace> sim( config );
    chooseTimeStep( sim.solver, sim.waveSpeedLimit() );
    removeFosResult( run.out_dir );
    std::filesystem::remove( run.out_dir + "/fos_history.json" );
    installInterruptHandler();
    ProgressPrinter printer( config.name, sim.particles.size(), run.progress );
    FosHistoryObserver observer( printer,
                                 static_cast<int>( config.stages.size() ) - 1,
                                 options.every_s );
    SnapshotWriter states( run.out_dir, "states" );
    nlohmann::json history = {
        { "case", config.name },
        { "case_file", config.file },
        { "overrides", config.overrides },
        { "every_s", options.every_s },
        { "stage", config.stages.back().name },
        { "criterion", describeCriterion( options.criterion ) },
        { "states", { { "hdf5", "states.h5" }, { "xdmf", "states.xdmf" } } },
        { "rows", nlohmann::json::array() } };
    FosOptions options_now = options;
    // One search of `searched` (a copy of the run's state, or the run
    // itself after its end), recorded under its stage time.
    const auto search =
        [&]( Simulation<ExecSpace>& searched, const RunProgress& at )
    {
        writeSnapshot( states, at, hostSnapshot( searched ) );
        const auto search_start = std::chrono::steady_clock::now();
        FosReport report = searchFos(
            searched, config, static_cast<std::size_t>( at.stage_index ),
            options_now, !run.progress );
        char folder[64];
        std::snprintf( folder, sizeof( folder ), "t_%07.2f", at.stage_time_s );
        const double search_s =
            std::chrono::duration<double>( std::chrono::steady_clock::now() -
                                           search_start )
                .count();
        writeFosResult( run.out_dir + "/" + folder, config, options_now, report,
                        search_s );
        history["rows"].push_back(
            fosHistoryRow( at, report, folder, search_s ) );
        history["wall_s"] = std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - wall_start )
                                .count();
        writeJsonAtomically( run.out_dir + "/fos_history.json", history );
        const FosSearchResult& s = report.search;
        std::cout << "t = " << at.stage_time_s << " s: "
                  << ( s.found
                           ? "factor of safety " + std::to_string( s.factor )
                           : "no factor of safety: " + s.status )
                  << " (" << report.trials.size() << " trials, " << search_s
                  << " s)" << std::endl;
        // The next search brackets from this factor in small steps.
        if ( s.found )
        {
            options_now.search.start = s.factor;
            options_now.search.step = std::min( options.search.step, 0.05 );
        }
    };
    StageLoopState loop;
    try
    {
        while ( true )
        {
            RunSummary summary;
            try
            {
                summary = runStages( sim, config, observer, loop );
            }
            catch ( const SimulationError& error )
            {
                printer.finish();
                std::cerr << "rainslide: error: the run stopped\n"
                          << error.what() << "\n";
                return 1;
            }
            printer.finish();
            std::optional<Checkpoint> state = observer.takeState();
            if ( !state )
            {
                if ( summary.interrupted )
                    return 130;
                // The stage's end, if it is a search time.
                const RunProgress at = observer.lastProgress();
                if ( observer.dueAt( at ) )
                    search( sim, at );
                states.finalize();
                return 0;
            }
            Simulation<ExecSpace> copy( config );
            restoreCheckpoint( copy, config, *state );
            search( copy, state->loop.progress );
            loop = state->loop;
        }
    }
    catch ( const FosInterrupted& stop )
    {
        printer.finish();
        const std::size_t finished = history["rows"].size();
        std::cerr << "rainslide: " << stop.what() << "; "
                  << ( finished ? "fos_history.json holds the " +
                                      std::to_string( finished ) +
                                      " searches finished before"
                                : std::string( "no search had finished" ) )
                  << "\n";
        return 130;
    }
}

} // namespace mpm

#endif // MPM_FOS_HISTORY_HPP
