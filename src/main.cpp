// rainslide: command-line interface.
//   rainslide run CASE [--out DIR] [--backend serial|openmp] [--threads N]
//                 [--restart CHECKPOINT] [--checkpoint-every-s S]
//                 [--stop-after-steps N] [--quiet]
//   rainslide fos CASE [--out DIR] [--restart CHECKPOINT] [--start F] ...
//                 (factor of safety by strength reduction)
//   rainslide check CASE
//   (all three: [--set KEY=VALUE]... overrides of the case's keys;
//          [--max-steps N] [--max-memory-gb X] [--max-output-gb X]
//          [--max-snapshots N], the budget of the run estimate)
#include <io/mpm_case_reader.hpp>
#include <io/mpm_output_folder.hpp>
#include <io/mpm_output_lock.hpp>
#include <mpm_config.hpp>
#include <setup/mpm_case_check.hpp>
#include <setup/mpm_run_estimate.hpp>
#include <solver/drivers/mpm_fos_history.hpp>
#include <solver/drivers/mpm_fos_run.hpp>
#include <solver/drivers/mpm_run_case.hpp>
#include <solver/output/mpm_progress.hpp>

#include <Kokkos_Core.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace
{
//! Exit codes: 0 success, 1 run failed (unstable), 2 bad input (also a
//! checkpoint that does not fit the case), 130 interrupted.
constexpr int exit_failed = 1;
constexpr int exit_bad_input = 2;
constexpr int exit_interrupted = 130;

int runWithKokkos( const mpm::CaseConfig& config, mpm::RunOptions options,
                   const mpm::FosOptions* fos )
{
    Kokkos::InitArguments args;
    args.num_threads = options.threads;
    args.disable_warnings = true;
    Kokkos::ScopeGuard guard( args );
    if ( fos && fos->every_s > 0.0 )
        return options.backend == "serial"
                   ? mpm::runFosHistory<Kokkos::Serial>( config, options, *fos )
                   : mpm::runFosHistory<Kokkos::OpenMP>( config, options,
                                                         *fos );
    if ( fos )
        return options.backend == "serial"
                   ? mpm::runFos<Kokkos::Serial>( config, options, *fos )
                   : mpm::runFos<Kokkos::OpenMP>( config, options, *fos );
    mpm::RunStatus status = mpm::RunStatus::Failed;
    if ( options.backend == "serial" )
    {
        options.threads = 1;
        status = mpm::runCase<Kokkos::Serial>( config, options );
    }
    else
        status = mpm::runCase<Kokkos::OpenMP>( config, options );
    switch ( status )
    {
    case mpm::RunStatus::Completed:
        return 0;
    case mpm::RunStatus::Interrupted:
        return exit_interrupted;
    case mpm::RunStatus::Failed:
        break;
    }
    return exit_failed;
}

//! The refusal of `check` for what `run` refuses before its first step
//! (firstStepRefusal on the Serial backend), "" if none.
std::string checkFirstStep( const mpm::CaseConfig& config )
{
    Kokkos::InitArguments args;
    args.num_threads = 1;
    args.disable_warnings = true;
    Kokkos::ScopeGuard guard( args );
    return mpm::firstStepRefusal<Kokkos::Serial>( config );
}

//! Interrupted before the run started: nothing was written.
int interruptedInSetUp()
{
    std::cerr << "rainslide: interrupted during set-up; nothing was written\n";
    return exit_interrupted;
}

void printCheckSummary( const mpm::CaseConfig& config,
                        const mpm::RunEstimate& estimate )
{
    std::cout << config.file << ": ok\n"
              << "  case " << config.name << ": grid " << config.grid.cells[0]
              << " x " << config.grid.cells[1] << " cells of "
              << config.grid.cell_size_m << " m, " << config.materials.size()
              << " material(s), " << config.bodies.size() << " body(ies), "
              << config.stages.size() << " stage(s)\n"
              << "  " << mpm::estimateSummary( estimate ) << "\n";
}

//! The budget options of `check` and `run`: each a non-negative limit,
//! 0 for none.
void addBudgetOptions( CLI::App& command, mpm::RunBudget& budget )
{
    const struct
    {
        const char* name;
        double& value;
        const char* help;
    } options[] = {
        { "--max-steps", budget.max_steps,
          "refuse a case whose estimated steps exceed this" },
        { "--max-memory-gb", budget.max_memory_gb,
          "refuse a case whose estimated memory exceeds this many GB" },
        { "--max-output-gb", budget.max_output_gb,
          "refuse a case whose estimated output exceeds this many GB" },
        { "--max-snapshots", budget.max_snapshots,
          "refuse a case that writes more snapshots" } };
    for ( const auto& option : options )
        command
            .add_option( option.name, option.value,
                         std::string( option.help ) + " (0 = no limit)" )
            ->check( CLI::NonNegativeNumber )
            ->capture_default_str();
}

//! The --set option of `check` and `run` (repeatable).
void addOverrideOption( CLI::App& command, std::vector<std::string>& overrides )
{
    command
        .add_option( "--set", overrides,
                     "override a key of the case: KEY=VALUE with KEY as the "
                     "case reader writes it and VALUE in TOML (e.g. --set "
                     "solver.courant_number=0.5 --set stages[1].duration_s=10; "
                     "strings quoted); repeatable, recorded in metrics.json" )
        ->allow_extra_args( false );
}
//! --backend, --threads and --quiet of `run` and `fos`.
void addExecutionOptions( CLI::App& command, mpm::RunOptions& options,
                          bool& quiet )
{
    command.add_option( "--backend", options.backend, "execution backend" )
        ->check( CLI::IsMember( { "serial", "openmp" } ) )
        ->capture_default_str();
    command.add_option( "--threads", options.threads, "OpenMP threads" )
        ->check( CLI::Range( 1, 1024 ) )
        ->capture_default_str();
    command.add_flag( "--quiet", quiet, "no progress lines" );
}

//! The options of `fos` that set the search and the failure criterion.
void addFosOptions( CLI::App& command, mpm::FosOptions& fos )
{
    mpm::FosSearchSettings& s = fos.search;
    mpm::FosCriterion& c = fos.criterion;
    const auto positive =
        [&]( const char* name, double& value, const std::string& help )
    {
        command.add_option( name, value, help )
            ->check( CLI::PositiveNumber )
            ->capture_default_str();
    };
    positive( "--start", s.start, "first trial strength-reduction factor F" );
    positive( "--step", s.step, "first bracketing step of F (doubles)" );
    positive( "--tolerance", s.tolerance,
              "the factor is found to +- this (bracket <= 2x)" );
    positive( "--min-factor", s.min_factor, "smallest F tried" );
    positive( "--max-factor", s.max_factor, "largest F tried" );
    command.add_option( "--max-trials", s.max_trials, "trials at most" )
        ->check( CLI::Range( 1, 1000 ) )
        ->capture_default_str();
    command
        .add_option( "--damping", c.damping,
                     "local damping of the trials, in [0, 1)" )
        ->check( CLI::Range( 0.0, 0.999 ) )
        ->capture_default_str();
    positive( "--periods", c.periods,
              "trial length in periods of the slowest skeleton wave" );
    positive( "--displacement-limit-m", c.displacement_limit_m,
              "fails if a displacement exceeds this (m)" );
    positive( "--creep-limit-m", c.creep_limit_m,
              "fails if the largest displacement grew by more than this (m) "
              "over the last quarter of a trial (and --energy-ratio holds)" );
    positive( "--energy-ratio", c.energy_ratio,
              "... while the mean kinetic energy of that quarter is above "
              "this fraction of the trial's peak" );
}
} // namespace

int main( int argc, char* argv[] )
{
    // First: Ctrl-C during set-up then ends with exit 130 (an inherited
    // "ignore" of a background job stays).
    mpm::installInterruptHandler();
    CLI::App app{ "rainslide " RAINSLIDE_VERSION
                  ": two-phase material point simulator of rainfall-induced "
                  "slope failure" };
    app.require_subcommand( 1 );

    std::string case_file;
    mpm::RunOptions options;
    options.backend = RAINSLIDE_DEFAULT_BACKEND;
    options.threads =
        std::max( 1, static_cast<int>( std::thread::hardware_concurrency() ) );
    bool quiet = false;
    mpm::RunBudget budget;
    std::vector<std::string> overrides;

    CLI::App* run = app.add_subcommand( "run", "run a case" );
    run->add_option( "case", case_file, "case file (TOML)" )->required();
    run->add_option( "--out", options.out_dir,
                     "output folder (default results/<case name>)" );
    addExecutionOptions( *run, options, quiet );
    run->add_option( "--restart", options.restart_file,
                     "continue the run from this checkpoint (written by an "
                     "earlier run of the same, unchanged case); --out "
                     "defaults to its folder" );
    run->add_option( "--checkpoint-every-s", options.checkpoint_interval_s,
                     "simulated seconds between checkpoints (overrides "
                     "solver.checkpoint_interval_s; 0 = only on Ctrl-C)" )
        ->check( CLI::NonNegativeNumber );
    run->add_option( "--stop-after-steps", options.stop_after_steps,
                     "stop as on Ctrl-C (checkpoint, exit 130) after this many "
                     "steps" )
        ->check( CLI::PositiveNumber );
    addBudgetOptions( *run, budget );
    addOverrideOption( *run, overrides );

    mpm::FosOptions fos_options;
    CLI::App* fos = app.add_subcommand(
        "fos", "factor of safety by strength reduction: run the case's stages "
               "(or take a checkpoint's state), then bisect the factor F "
               "dividing c and tan(phi) at which a damped trial fails; "
               "writes DIR/fos.json" );
    fos->add_option( "case", case_file, "case file (TOML)" )->required();
    fos->add_option( "--out", options.out_dir,
                     "output folder (default results/<case name>_fos)" );
    addExecutionOptions( *fos, options, quiet );
    fos->add_option( "--restart", options.restart_file,
                     "search from this checkpoint's state (an earlier run of "
                     "the same case) instead of running the stages" )
        ->check( CLI::ExistingFile );
    fos->add_option( "--every-s", fos_options.every_s,
                     "a factor-of-safety history: search at the start of the "
                     "last stage and every this many simulated seconds of it "
                     "(writes fos_history.json, one t_<time>/ folder each)" )
        ->check( CLI::PositiveNumber )
        ->excludes( "--restart" );
    addFosOptions( *fos, fos_options );
    addBudgetOptions( *fos, budget );
    addOverrideOption( *fos, overrides );

    CLI::App* check = app.add_subcommand( "check", "validate a case file" );
    check->add_option( "case", case_file, "case file (TOML)" )->required();
    addBudgetOptions( *check, budget );
    addOverrideOption( *check, overrides );

    // A bad option is bad input (exit 2), as a bad case file is; --help 0.
    try
    {
        app.parse( argc, argv );
    }
    catch ( const CLI::ParseError& error )
    {
        const int code = app.exit( error );
        return code == 0 ? 0 : exit_bad_input;
    }
    if ( fos->parsed() &&
         !( fos_options.search.min_factor < fos_options.search.max_factor ) )
    {
        std::cerr << "rainslide: error: --min-factor must be below "
                     "--max-factor, found "
                  << fos_options.search.min_factor << " and "
                  << fos_options.search.max_factor << "\n";
        return exit_bad_input;
    }

    mpm::CaseCheck case_check;
    try
    {
        case_check = mpm::checkCase( case_file, overrides, budget );
    }
    catch ( const mpm::CaseError& error )
    {
        std::cerr << error.what() << "\n";
        return exit_bad_input;
    }
    // Refused: cannot finish, over the budget, or errors of the points.
    if ( !case_check.ok() )
    {
        std::cerr << mpm::checkErrorReport( case_check );
        return exit_bad_input;
    }
    const mpm::CaseConfig& config = case_check.config;
    const mpm::RunEstimate& estimate = case_check.estimate;
    // Warnings of the reader (a valid case, probably not as meant); those
    // of the points only for `check`: a run warns at each stage start.
    for ( const std::string& warning : config.warnings )
        std::cerr << warning << "\n";
    if ( check->parsed() )
        for ( const std::string& warning : case_check.point_warnings )
            std::cerr << config.file << ": warning: " << warning << "\n";
    if ( mpm::interruptRequested() )
        return interruptedInSetUp();
    if ( check->parsed() )
    {
        // What a run refuses once the simulation is built (the points
        // generated: a case too large for the point checks skips it).
        const std::string refusal =
            case_check.points_checked ? checkFirstStep( config ) : "";
        if ( mpm::interruptRequested() )
            return interruptedInSetUp();
        if ( !refusal.empty() )
        {
            std::cerr << config.file << ": error: " << refusal << "\n";
            return exit_bad_input;
        }
        printCheckSummary( config, estimate );
        return 0;
    }
    // A strength reduction needs a skeleton that can move and fail.
    if ( fos->parsed() &&
         ( config.solver.scheme == mpm::TwoPhaseScheme::Seepage ||
           config.solver.scheme == mpm::TwoPhaseScheme::QuasiStatic ||
           config.solver.scheme == mpm::TwoPhaseScheme::Auto ) )
    {
        const mpm::TwoPhaseScheme scheme = config.solver.scheme;
        std::cerr << config.file
                  << ": error: key 'solver.scheme': rainslide fos needs a "
                     "dynamic scheme (\"explicit\" or \"semi_implicit\"), "
                     "found "
                  << ( scheme == mpm::TwoPhaseScheme::Seepage
                           ? "\"seepage\", which holds the skeleton\n"
                       : scheme == mpm::TwoPhaseScheme::QuasiStatic
                           ? "\"quasi_static\", which stops when the soil "
                             "fails\n"
                           : "\"auto\", whose trials would not be dynamic "
                             "throughout (--set solver.scheme=\"semi_implicit"
                             "\" runs them as auto runs a failure)\n" );
        return exit_bad_input;
    }
    if ( fos->parsed() && options.out_dir.empty() )
        options.out_dir = "results/" + config.name + "_fos";
    if ( options.out_dir.empty() && !options.restart_file.empty() )
    {
        const auto folder =
            std::filesystem::path( options.restart_file ).parent_path();
        options.out_dir = folder.empty() ? "." : folder.string();
    }
    if ( options.out_dir.empty() )
        options.out_dir = "results/" + config.name;
    for ( const std::string& unsafe :
          { mpm::unsafeOutputFolder( options.out_dir ),
            mpm::caseFilesInOutputFolder( options.out_dir, config.file ) } )
        if ( !unsafe.empty() )
        {
            std::cerr << "rainslide: error: --out '" << options.out_dir
                      << "': " << unsafe << "\n";
            return exit_bad_input;
        }
    options.progress = !quiet;
    try
    {
        const mpm::OutputLock lock( options.out_dir );
        if ( mpm::interruptRequested() )
            return interruptedInSetUp();
        return runWithKokkos( config, options,
                              fos->parsed() ? &fos_options : nullptr );
    }
    catch ( const mpm::OutputFolderError& error )
    {
        std::cerr << "rainslide: error: " << error.what() << "\n";
        return exit_bad_input;
    }
    catch ( const mpm::RunRefused& error )
    {
        std::cerr << "rainslide: error: " << error.what() << "\n";
        return exit_bad_input;
    }
    catch ( const mpm::SimulationError& error )
    {
        std::cerr << "rainslide: error: " << error.what() << "\n";
        return exit_failed;
    }
    catch ( const std::exception& error )
    {
        std::cerr << "rainslide: error: " << error.what() << "\n";
        return exit_failed;
    }
}
