#include <case/mpm_geometry.hpp>
#include <setup/mpm_run_estimate.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mpm
{
namespace
{
// Sizes of the data layout, bytes (views/, the host snapshot and its
// HDF5 fields in src/solver/output/mpm_progress.cpp), rounded up.
constexpr double point_bytes_dry = 700.0;
constexpr double point_bytes_water = 400.0;
constexpr double node_bytes_dry = 400.0;
constexpr double node_bytes_water = 400.0;
constexpr double snapshot_point_bytes_dry = 17 * 8 + 3 * 4;
constexpr double snapshot_point_bytes_water = 6 * 8;
// A row of probes.csv: time, stage, name, id and the probed fields at nine
// digits (about 140 bytes).
constexpr double probe_row_bytes = 160.0;

// More steps than this never end (1e12 steps of 1 us are 11 days).
constexpr double max_possible_steps = 1.0e12;

//! Initial P-wave speed of a material at rest, m/s (mpm_timestep.hpp).
double waveSpeed( const CaseConfig& config, const MaterialConfig& m )
{
    const double nu = m.poisson_ratio;
    const double e_c = m.youngs_modulus_pa * ( 1.0 - nu ) /
                       ( ( 1.0 + nu ) * ( 1.0 - 2.0 * nu ) );
    if ( config.analysis == AnalysisType::Dry )
        return std::sqrt( e_c / m.density_kg_per_m3 );
    // Saturated: the undrained mixture wave and the pore-water wave.
    const double n = m.porosity, k_w = config.water.bulk_modulus_pa;
    const double rho_w = config.water.density_kg_per_m3;
    const double rho_m = ( 1.0 - n ) * m.solid_density_kg_per_m3 + n * rho_w;
    const double mixture = std::sqrt( ( e_c + k_w / n ) / rho_m );
    const double water = std::sqrt( k_w / rho_w );
    return std::max( mixture, water );
}

std::string number( const double v )
{
    char buf[32];
    std::snprintf( buf, sizeof buf, "%.3g", v );
    return buf;
}

//! A count: in full below 10^7 ("169513"), else "2e+11".
std::string count( const double v )
{
    if ( !( v < 1.0e7 ) )
        return number( v );
    char buf[32];
    std::snprintf( buf, sizeof buf, "%.0f", v );
    return buf;
}

std::string gigabytes( const double bytes )
{
    return number( bytes / 1.0e9 ) + " GB";
}

} // namespace

//---------------------------------------------------------------------------//
RunEstimate estimateRun( const CaseConfig& config )
{
    RunEstimate e;
    const GridConfig& g = config.grid;
    const double h = g.cell_size_m;
    e.cells = static_cast<double>( g.cells[0] ) * g.cells[1];
    e.nodes = ( g.cells[0] + 1.0 ) * ( g.cells[1] + 1.0 );
    const double ppc = config.points_per_cell_per_direction;
    for ( const BodyConfig& body : config.bodies )
        e.points +=
            geometry::polygonArea( body.polygon_m ) / ( h * h ) * ppc * ppc;
    e.points = std::min( e.points, e.cells * ppc * ppc );

    // Fastest wave over the case's and every stage's materials.
    auto consider = [&]( const std::vector<MaterialConfig>& materials )
    {
        for ( const MaterialConfig& m : materials )
        {
            const double c = waveSpeed( config, m );
            if ( !( c <= e.max_wave_speed_m_per_s ) )
            {
                e.max_wave_speed_m_per_s = c;
                e.fastest_material = m.name;
            }
        }
    };
    consider( config.materials );
    for ( const StageConfig& stage : config.stages )
        consider( stage.materials );

    const SolverConfig& s = config.solver;
    // The seepage step is set by the flow as it runs (the quasi-static and
    // auto schemes' too, while quasi-static): its first step bounds the
    // estimate (it grows from there while the flow allows).
    const bool seepage = s.scheme == TwoPhaseScheme::Seepage ||
                         s.scheme == TwoPhaseScheme::QuasiStatic ||
                         s.scheme == TwoPhaseScheme::Auto;
    const double dt = s.dt_s > 0.0 ? s.dt_s
                      : seepage    ? s.seepage_initial_dt_s
                                   : s.courant_number * h *
                                      std::sqrt( s.inertia_scaling ) /
                                      e.max_wave_speed_m_per_s;
    for ( const StageConfig& stage : config.stages )
    {
        StageEstimate st;
        st.name = stage.name;
        st.dt_s = std::isfinite( dt ) ? dt : 0.0;
        st.snapshots =
            1.0 + static_cast<double>( stage.snapshot_times_s.size() );
        if ( stage.snapshot_interval_s > 0.0 )
            st.snapshots +=
                std::floor( stage.duration_s / stage.snapshot_interval_s );
        st.steps = st.dt_s > 0.0
                       ? std::ceil( stage.duration_s / st.dt_s ) + st.snapshots
                       : std::numeric_limits<double>::infinity();
        e.steps += st.steps;
        e.snapshots += st.snapshots;
        if ( config.probes.interval_s > 0.0 )
            e.probe_rows +=
                static_cast<double>( config.probes.points.size() ) *
                std::min( st.steps,
                          1.0 + std::floor( stage.duration_s /
                                            config.probes.interval_s ) );
        e.stages.push_back( st );
    }

    const bool water = config.analysis != AnalysisType::Dry;
    const double point_bytes =
        point_bytes_dry + ( water ? point_bytes_water : 0.0 );
    const double node_bytes =
        node_bytes_dry + ( water ? node_bytes_water : 0.0 );
    e.memory_bytes = e.points * point_bytes + e.nodes * node_bytes;
    const double snapshot_bytes =
        snapshot_point_bytes_dry + ( water ? snapshot_point_bytes_water : 0.0 );
    e.output_bytes =
        e.snapshots * e.points * snapshot_bytes +
        e.probe_rows * probe_row_bytes +
        ( s.checkpoint_interval_s > 0.0 ? e.points * point_bytes : 0.0 );
    return e;
}

//---------------------------------------------------------------------------//
std::vector<std::string> runRefusals( const CaseConfig& config,
                                      const RunEstimate& e,
                                      const RunBudget& budget,
                                      bool& cannot_finish )
{
    std::vector<std::string> refusals;
    cannot_finish = false;
    const bool fixed = config.solver.dt_s > 0.0;
    const std::string dt_source =
        fixed ? "solver.dt_s = " + number( config.solver.dt_s ) + " s"
        : config.solver.scheme == TwoPhaseScheme::Seepage ||
                config.solver.scheme == TwoPhaseScheme::QuasiStatic ||
                config.solver.scheme == TwoPhaseScheme::Auto
            ? "solver.seepage_initial_dt_s = " +
                  number( config.solver.seepage_initial_dt_s ) +
                  " s, the flow's first step"
            : "solver.courant_number = " +
                  number( config.solver.courant_number ) +
                  " x cell_size_m / P-wave speed " +
                  number( e.max_wave_speed_m_per_s ) + " m/s of material '" +
                  e.fastest_material + "'";

    // A time step that cannot advance the time: never ends.
    for ( std::size_t k = 0; k < e.stages.size() && !cannot_finish; ++k )
    {
        const StageEstimate& st = e.stages[k];
        const double duration = config.stages[k].duration_s;
        if ( st.dt_s > 0.0 && duration + st.dt_s > duration &&
             st.steps <= max_possible_steps )
            continue;
        cannot_finish = true;
        const double time_steps =
            st.dt_s > 0.0 ? std::ceil( duration / st.dt_s ) : st.steps;
        if ( time_steps <= max_possible_steps && st.dt_s > 0.0 &&
             duration + st.dt_s > duration )
        {
            // The snapshots (each shortens a step to land on it) are too many.
            refusals.push_back(
                "stages[" + std::to_string( k ) + "] '" + st.name +
                "' cannot finish: expected at most " +
                number( max_possible_steps ) + " steps, found " +
                number( st.snapshots ) + " snapshots (duration_s = " +
                number( duration ) + " s / snapshot_interval_s = " +
                number( config.stages[k].snapshot_interval_s ) +
                " s), each a step; raise snapshot_interval_s" );
            continue;
        }
        refusals.push_back(
            "stages[" + std::to_string( k ) + "] '" + st.name +
            "' cannot finish: expected a time step that ends duration_s = " +
            number( duration ) + " s in at most " +
            number( max_possible_steps ) +
            " steps, found dt = " + number( st.dt_s ) + " s (" + dt_source +
            "); check the material densities and moduli, "
            "solver.courant_number and solver.dt_s" );
    }
    if ( cannot_finish )
        return refusals;

    auto over = [&]( const double value, const double limit,
                     const std::string& what, const std::string& option,
                     const std::string& detail )
    {
        const bool counted = what.find( "GB" ) == std::string::npos;
        auto text = [counted]( const double v )
        { return counted ? count( v ) : number( v ); };
        if ( limit > 0.0 && value > limit )
            refusals.push_back( "the run exceeds the budget: " + what + " " +
                                text( value ) + " > " + text( limit ) + " (" +
                                detail + "); raise the limit with " + option +
                                " (0 = no limit) or change the case" );
    };
    std::string steps_detail =
        "dt " + number( e.stages.empty() ? 0.0 : e.stages[0].dt_s ) +
        " s from " + dt_source;
    over( e.steps, budget.max_steps, "estimated steps", "--max-steps N",
          steps_detail );
    over( e.snapshots, budget.max_snapshots, "snapshots", "--max-snapshots N",
          "duration_s / snapshot_interval_s + snapshot_times_s + 1 per stage" );
    over( e.memory_bytes / 1.0e9, budget.max_memory_gb, "estimated memory (GB)",
          "--max-memory-gb X",
          number( e.points ) + " points, " + number( e.cells ) + " cells" );
    over( e.output_bytes / 1.0e9, budget.max_output_gb, "estimated output (GB)",
          "--max-output-gb X",
          number( e.snapshots ) + " snapshots of " + number( e.points ) +
              " points, " + count( e.probe_rows ) + " rows of probes.csv" );
    return refusals;
}

//---------------------------------------------------------------------------//
std::string estimateSummary( const RunEstimate& e )
{
    return "estimate: " + count( e.points ) + " points, " + count( e.cells ) +
           " cells, dt " + number( e.stages.empty() ? 0.0 : e.stages[0].dt_s ) +
           " s, at most " + count( e.steps ) + " steps, " +
           count( e.snapshots ) + " snapshots, memory " +
           gigabytes( e.memory_bytes ) + ", output " +
           gigabytes( e.output_bytes );
}

} // namespace mpm
