#include <solver/output/mpm_progress.hpp>

#include <records/mpm_point_fields.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>

#include <signal.h>

namespace mpm
{
namespace
{
std::atomic<bool> interrupt_flag{ false };

extern "C" void onInterrupt( int ) { interrupt_flag.store( true ); }
} // namespace

void installInterruptHandler()
{
    for ( const int signal : { SIGINT, SIGTERM } )
    {
        struct sigaction now = {};
        if ( ::sigaction( signal, nullptr, &now ) != 0 ||
             now.sa_handler == SIG_IGN || now.sa_handler == onInterrupt )
            continue;
        struct sigaction handler = {};
        handler.sa_handler = onInterrupt;
        sigemptyset( &handler.sa_mask );
        ::sigaction( signal, &handler, nullptr );
    }
}

bool interruptRequested() { return interrupt_flag.load(); }

void printResumeHint( const std::string& case_file,
                      const std::string& run_options,
                      const std::string& checkpoint_file,
                      const long checkpoint_step,
                      const double checkpoint_time_s )
{
    if ( checkpoint_step < 0 )
    {
        std::fprintf( stderr,
                      "rainslide: interrupted; no checkpoint could be written "
                      "(see the warning above)\n" );
        return;
    }
    std::fprintf( stderr,
                  "rainslide: interrupted; checkpoint at step %ld (t = %.6g s) "
                  "in %s\n"
                  "  continue with: rainslide run %s --restart %s %s\n",
                  checkpoint_step, checkpoint_time_s, checkpoint_file.c_str(),
                  case_file.c_str(), checkpoint_file.c_str(),
                  run_options.c_str() );
}

//---------------------------------------------------------------------------//
ProgressPrinter::ProgressPrinter( const std::string& case_name,
                                  const int num_points, const bool enabled,
                                  const double interval_s )
    : _case_name( case_name )
    , _num_points( num_points )
    , _enabled( enabled )
    , _interval_s( interval_s )
    , _start( clock::now() )
    , _last_print( clock::now() )
    , _stage_start( clock::now() )
{
}

void ProgressPrinter::update( const RunProgress& progress )
{
    if ( progress.stage_step == 1 || !_has_baseline )
    {
        _has_baseline = true;
        _stage_start = clock::now();
        _stage_start_step = progress.step - 1;
        _stage_start_time_s = progress.stage_time_s - progress.dt_s;
    }
    const auto now = clock::now();
    if ( !_enabled ||
         std::chrono::duration<double>( now - _last_print ).count() <
             _interval_s )
        return;
    _last_print = now;
    const double wall = std::chrono::duration<double>( now - _start ).count();
    const double stage_wall =
        std::chrono::duration<double>( now - _stage_start ).count();
    const double done_s = progress.stage_time_s - _stage_start_time_s;
    const double eta =
        done_s > 0.0
            ? stage_wall *
                  ( progress.stage_duration_s - progress.stage_time_s ) / done_s
            : 0.0;
    const double rate = stage_wall > 0.0
                            ? double( progress.step - _stage_start_step ) *
                                  progress.active_points / stage_wall
                            : 0.0;
    std::fprintf(
        stderr,
        "[%s] stage %s  step %ld  t = %.4g s (stage %.4g / %.4g s)  "
        "dt = %.3g s  wall %.1f s  stage ETA <= %.0f s  %.3g MP-updates/s\n",
        _case_name.c_str(), progress.stage.c_str(), progress.step,
        progress.time_s, progress.stage_time_s, progress.stage_duration_s,
        progress.dt_s, wall, eta, rate );
}

void ProgressPrinter::stageEnd( const RunProgress& progress,
                                const StageSummary& summary )
{
    if ( !_enabled )
        return;
    std::fprintf( stderr, "[%s] stage %s finished: %ld steps, %.4g s simulated",
                  _case_name.c_str(), summary.name.c_str(), summary.steps,
                  summary.duration_s );
    if ( summary.type == "quasi_static" )
        std::fprintf( stderr, ", kinetic-energy ratio %.3g (%s)",
                      summary.ke_ratio,
                      summary.converged ? "converged" : "NOT converged" );
    else if ( summary.stop_reason == "static_again" )
        std::fprintf( stderr, ", static again" );
    std::fprintf( stderr, ", %d active points\n", progress.active_points );
}

void ProgressPrinter::finish() { std::fflush( stderr ); }

void ProgressPrinter::summary( const nlohmann::json& metrics ) const
{
    std::fprintf(
        stderr,
        "[%s] %s: %ld steps, %.4g s simulated, wall %.2f s, %.3g "
        "MP-updates/s, %d points, backend %s with %d thread(s)\n"
        "[%s] results: %s, metrics: %s/metrics.json\n",
        _case_name.c_str(), metrics.value( "status", std::string() ).c_str(),
        metrics.value( "steps", 0L ), metrics.value( "simulated_time_s", 0.0 ),
        metrics.value( "wall_s", 0.0 ),
        metrics.value( "mp_updates_per_s", 0.0 ), _num_points,
        metrics.value( "backend", std::string() ).c_str(),
        metrics.value( "threads", 1 ), _case_name.c_str(),
        metrics["output"].value( "xdmf", std::string() ).c_str(),
        metrics.value( "output_dir", std::string( "." ) ).c_str() );
}

//---------------------------------------------------------------------------//
void writeSnapshot( SnapshotWriter& writer, const RunProgress& progress,
                    const HostSnapshot& snap )
{
    std::vector<FieldRef> fields;
    for ( const PointField& f : pointFields() )
        if ( !f.two_phase || !snap.p_w.empty() )
            fields.push_back(
                { f.name, ( snap.*f.values ).data(), f.components, f.unit } );
    std::vector<IntFieldRef> int_fields;
    for ( const IntPointField& f : intPointFields() )
        int_fields.push_back( { f.name, ( snap.*f.values ).data() } );
    writer.write( progress.time_s, progress.stage, progress.stage_time_s,
                  progress.step, snap.num_points, fields, int_fields );
}

} // namespace mpm
