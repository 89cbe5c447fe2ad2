#include <io/mpm_probe_recorder.hpp>
#include <io/mpm_safe_file.hpp>
#include <records/mpm_point_fields.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace mpm
{
namespace
{
constexpr double gravity_for_K = 9.81; // m/s^2

//! Shortest text that reads back as exactly t (a restart compares times).
std::string timeText( const double t )
{
    char buf[32];
    const auto result = std::to_chars( buf, buf + sizeof buf, t );
    return std::string( buf, result.ptr );
}

//! The first multiple of interval after t (t itself counts as passed).
double nextMultiple( const double t, const double interval )
{
    return interval * ( std::floor( t / interval * ( 1.0 + 1.0e-12 ) ) + 1.0 );
}
} // namespace

//---------------------------------------------------------------------------//
ProbeRecorder::ProbeRecorder( const CaseConfig& config,
                              const HostSnapshot& initial,
                              const std::string& out_dir )
    : _interval_s( config.probes.interval_s )
    , _path( out_dir + "/probes.csv" )
{
    if ( config.probes.points.empty() )
        return;
    const bool dry = config.analysis == AnalysisType::Dry;
    for ( const MaterialConfig& m : config.materials )
        _K_of_material.push_back(
            dry ? 0.0
                : m.permeability_m2 * config.water.density_kg_per_m3 *
                      gravity_for_K / config.water.viscosity_pa_s );
    for ( const ProbeConfig& wanted : config.probes.points )
    {
        Probe probe;
        probe.name = wanted.name;
        double best = std::numeric_limits<double>::infinity();
        for ( int p = 0; p < initial.num_points; ++p )
        {
            const double d =
                std::hypot( initial.x[2 * p] - wanted.position_m[0],
                            initial.x[2 * p + 1] - wanted.position_m[1] );
            if ( d < best )
            {
                best = d;
                probe.point = p;
            }
        }
        if ( best > config.grid.cell_size_m )
            throw std::runtime_error(
                config.file + ": probes: the point '" + wanted.name + "' at [" +
                std::to_string( wanted.position_m[0] ) + ", " +
                std::to_string( wanted.position_m[1] ) +
                "] m is not in the soil: the nearest material point is " +
                std::to_string( best ) +
                " m away (more than one cell); move it inside a body" );
        probe.distance_m = best;
        _probes.push_back( probe );
    }
}

//---------------------------------------------------------------------------//
ProbeRecorder::~ProbeRecorder()
{
    if ( _fd >= 0 )
        ::close( _fd );
}

//---------------------------------------------------------------------------//
void ProbeRecorder::open( const double resume_time_s )
{
    if ( _probes.empty() )
        return;
    const std::string partial = _path + ".partial";
    // Rows of the interrupted session up to the restart time.
    std::vector<std::string> kept;
    double last_kept_s = -1.0;
    if ( resume_time_s >= 0.0 )
    {
        std::ifstream earlier( _path );
        if ( !earlier )
            earlier.open( partial );
        std::string line;
        std::getline( earlier, line ); // header
        for ( long row = 2; std::getline( earlier, line ); ++row )
        {
            const std::string time = line.substr( 0, line.find( ',' ) );
            char* end = nullptr;
            const double t = std::strtod( time.c_str(), &end );
            if ( time.empty() || *end != '\0' || !std::isfinite( t ) )
                throw std::runtime_error(
                    "cannot continue '" + _path + "': line " +
                    std::to_string( row ) +
                    ": expected the time in s as the first column, found '" +
                    time.substr( 0, 40 ) + "'" );
            // Times are written exactly (timeText): rows up to the
            // checkpoint's time are the uninterrupted run's.
            if ( t <= resume_time_s )
            {
                kept.push_back( line );
                last_kept_s = std::max( last_kept_s, t );
            }
        }
    }
    std::remove( _path.c_str() );
    std::error_code ec; // a failure shows when the file is opened
    std::filesystem::create_directories(
        std::filesystem::path( _path ).parent_path(), ec );
    _fd = createExclusive( partial ); // a planted symlink is not followed
    _failed = false;
    std::string text = "time_s,stage,name,point_id";
    for ( const PointField& field : pointFields() )
        if ( field.probe_columns )
            text += std::string( "," ) + field.probe_columns;
    text += ",K_m_per_s\n";
    for ( const std::string& line : kept )
        text += line + '\n';
    append( text );
    // Due next as in the uninterrupted run: after the last row recorded
    // (not after the checkpoint's time, which may lie a rounding error
    // below a due time whose row the uninterrupted run writes next step).
    _next_time_s =
        last_kept_s < 0.0 ? 0.0 : nextMultiple( last_kept_s, _interval_s );
}

//---------------------------------------------------------------------------//
void ProbeRecorder::record( const RunProgress& progress,
                            const HostSnapshot& snapshot )
{
    std::ostringstream rows;
    rows << std::setprecision( 9 );
    for ( const Probe& probe : _probes )
    {
        const int p = probe.point;
        rows << timeText( progress.time_s ) << ',' << progress.stage << ','
             << probe.name << ',' << snapshot.id[p];
        // The probed fields of the registry (nan: none in a dry scene).
        for ( const PointField& field : pointFields() )
        {
            if ( !field.probe_columns )
                continue;
            const std::vector<double>& values = snapshot.*field.values;
            for ( int c = 0; c < field.components; ++c )
            {
                rows << ',';
                if ( values.empty() )
                    rows << "nan";
                else
                    rows << values[field.components * p + c];
            }
        }
        rows << ',' << _K_of_material[snapshot.material[p]] << '\n';
    }
    append( rows.str() );
    _next_time_s = nextMultiple( progress.time_s, _interval_s );
}

//---------------------------------------------------------------------------//
void ProbeRecorder::append( const std::string& text )
{
    if ( _fd >= 0 && !_failed && !writeAll( _fd, text ) )
        _failed = true;
}

//---------------------------------------------------------------------------//
void ProbeRecorder::finish()
{
    if ( _fd < 0 )
        return;
    if ( ::close( _fd ) != 0 )
        _failed = true;
    _fd = -1;
    if ( !_failed )
        std::rename( ( _path + ".partial" ).c_str(), _path.c_str() );
    _next_time_s = 1.0e300;
}

} // namespace mpm
