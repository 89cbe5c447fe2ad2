#include <solver/output/mpm_failure_verdict.hpp>

#include <mpm_device_type.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace mpm
{
namespace
{
int findRoot( std::vector<int>& parent, int i )
{
    while ( parent[i] != i )
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

//! Square root of the median positive point volume (area in plane strain).
double pointSpacing( const HostSnapshot& snapshot )
{
    std::vector<double> volumes;
    for ( int p = 0; p < snapshot.num_points; ++p )
        if ( snapshot.vol[p] > 0.0 )
            volumes.push_back( snapshot.vol[p] );
    if ( volumes.empty() )
        return 0.0;
    const std::size_t mid = volumes.size() / 2;
    std::nth_element( volumes.begin(), volumes.begin() + mid, volumes.end() );
    double median = volumes[mid];
    if ( volumes.size() % 2 == 0 )
        median = 0.5 * ( median + *std::max_element( volumes.begin(),
                                                     volumes.begin() + mid ) );
    return std::sqrt( median );
}

std::string format( const char* pattern, double a, double b = 0.0,
                    double c = 0.0, double d = 0.0 )
{
    char buffer[256];
    std::snprintf( buffer, sizeof buffer, pattern, a, b, c, d );
    return buffer;
}
} // namespace

std::vector<int> linkedGroups( const std::vector<double>& xy,
                               const double link_m )
{
    const int n = static_cast<int>( xy.size() / 2 );
    std::vector<int> parent( n );
    std::iota( parent.begin(), parent.end(), 0 );
    // Bins of the link size: neighbours closer than it are in adjacent bins.
    auto bin = [link_m]( double v ) { return std::floor( v / link_m ); };
    auto key = []( long long i, long long j ) { return i * 4000037LL + j; };
    std::unordered_map<long long, std::vector<int>> bins;
    for ( int p = 0; p < n; ++p )
        bins[key( bin( xy[2 * p] ), bin( xy[2 * p + 1] ) )].push_back( p );
    const double link2 = link_m * link_m;
    for ( int p = 0; p < n; ++p )
    {
        const long long bi = bin( xy[2 * p] ), bj = bin( xy[2 * p + 1] );
        for ( long long di = -1; di <= 1; ++di )
            for ( long long dj = -1; dj <= 1; ++dj )
            {
                const auto found = bins.find( key( bi + di, bj + dj ) );
                if ( found == bins.end() )
                    continue;
                for ( const int q : found->second )
                {
                    if ( q <= p )
                        continue;
                    const double dx = xy[2 * p] - xy[2 * q];
                    const double dy = xy[2 * p + 1] - xy[2 * q + 1];
                    if ( dx * dx + dy * dy < link2 )
                        parent[findRoot( parent, p )] = findRoot( parent, q );
                }
            }
    }
    std::vector<int> label( n, -1 ), root_label( n, -1 );
    int groups = 0;
    for ( int p = 0; p < n; ++p )
    {
        const int root = findRoot( parent, p );
        if ( root_label[root] < 0 )
            root_label[root] = groups++;
        label[p] = root_label[root];
    }
    return label;
}

FailureVerdict::FailureVerdict( std::vector<bool> analysed_stages,
                                VerdictThresholds thresholds )
    : _analysed( std::move( analysed_stages ) )
    , _thresholds( thresholds )
{
}

long long FailureVerdict::heightBand( const double y ) const
{
    const double height = _spacing_m > 0.0 ? _spacing_m : 1.0;
    return static_cast<long long>(
        std::clamp( std::floor( y / height ), -1.0e15, 1.0e15 ) );
}

void FailureVerdict::setReference( const HostSnapshot& snapshot,
                                   const bool from_displacement )
{
    int max_id = 0;
    for ( int p = 0; p < snapshot.num_points; ++p )
        max_id = std::max( max_id, snapshot.id[p] );
    _ref_index.assign( max_id + 1, -1 );
    _ref_x.assign( 2 * snapshot.num_points, 0.0 );
    for ( int p = 0; p < snapshot.num_points; ++p )
    {
        _ref_index[snapshot.id[p]] = p;
        for ( int d = 0; d < 2; ++d )
            _ref_x[2 * p + d] =
                snapshot.x[2 * p + d] -
                ( from_displacement ? snapshot.displacement[2 * p + d] : 0.0 );
    }
    _outline.clear();
    for ( int p = 0; p < snapshot.num_points; ++p )
    {
        if ( snapshot.status[p] != point_active )
            continue;
        const double x = _ref_x[2 * p];
        const auto [it, inserted] =
            _outline.try_emplace( heightBand( _ref_x[2 * p + 1] ), x, x );
        it->second.first = std::min( it->second.first, x );
        it->second.second = std::max( it->second.second, x );
    }
    if ( _ever.size() < _ref_index.size() )
        _ever.resize( _ref_index.size(), 0 );
}

void FailureVerdict::add( const RunProgress& progress,
                          const HostSnapshot& snapshot )
{
    if ( snapshot.num_points == 0 )
        return;
    if ( _spacing_m <= 0.0 )
        _spacing_m = pointSpacing( snapshot );
    const int stage = progress.stage_index;
    if ( stage != _reference_stage )
    {
        // No stage end seen before it (the first stage, or a restart):
        // the positions at the last displacement reset.
        setReference( snapshot, true );
        _reference_stage = stage;
        _prev_time_s = progress.time_s - progress.stage_time_s;
    }
    if ( stage < static_cast<int>( _analysed.size() ) && _analysed[stage] )
        analyse( progress, snapshot );
}

void FailureVerdict::endStage( const RunProgress& progress,
                               const HostSnapshot& end_state )
{
    if ( end_state.num_points == 0 )
        return;
    if ( _spacing_m <= 0.0 )
        _spacing_m = pointSpacing( end_state );
    setReference( end_state, false );
    _reference_stage = progress.stage_index + 1;
    _prev_time_s = progress.time_s;
}

void FailureVerdict::analyse( const RunProgress& progress,
                              const HostSnapshot& snapshot )
{
    const VerdictThresholds& th = _thresholds;
    const double link = th.link_factor * _spacing_m;
    const int n = snapshot.num_points;
    const double t = progress.time_s;
    if ( _first_time_s < 0.0 )
        _first_time_s = t;
    _last_time_s = t;
    ++_snapshots_analysed;

    // Sliding points, their displacement and reference slot.
    std::vector<int> slot( n, -1 ), sliding;
    std::vector<double> sliding_xy;
    for ( int p = 0; p < n; ++p )
    {
        const int id = snapshot.id[p];
        if ( snapshot.status[p] != point_active ||
             id >= static_cast<int>( _ref_index.size() ) || _ref_index[id] < 0 )
            continue;
        slot[p] = _ref_index[id];
        const double ux = snapshot.x[2 * p] - _ref_x[2 * slot[p]];
        const double uy = snapshot.x[2 * p + 1] - _ref_x[2 * slot[p] + 1];
        const double u = std::sqrt( ux * ux + uy * uy );
        if ( u > _max_displacement_m )
        {
            _max_displacement_m = u;
            _max_displacement_time_s = t;
            _max_displacement_x_m = _ref_x[2 * slot[p]];
            _max_displacement_y_m = _ref_x[2 * slot[p] + 1];
        }
        if ( ( u > th.disp_threshold_m &&
               snapshot.eps_p_bar[p] > th.eps_threshold ) ||
             u > th.moved_threshold_m )
        {
            sliding.push_back( p );
            sliding_xy.push_back( snapshot.x[2 * p] );
            sliding_xy.push_back( snapshot.x[2 * p + 1] );
        }
    }

    // Counted groups: linked sliding points of at least the minimum area.
    const std::vector<int> label = linkedGroups( sliding_xy, link );
    std::vector<double> group_area;
    for ( std::size_t k = 0; k < sliding.size(); ++k )
    {
        if ( label[k] >= static_cast<int>( group_area.size() ) )
            group_area.resize( label[k] + 1, 0.0 );
        group_area[label[k]] += snapshot.vol[sliding[k]];
    }
    std::vector<int> counted_points; // indices into `sliding`
    double area = 0.0;
    for ( std::size_t k = 0; k < sliding.size(); ++k )
        if ( group_area[label[k]] >= th.min_group_area_m2 )
        {
            counted_points.push_back( static_cast<int>( k ) );
            area += snapshot.vol[sliding[k]];
        }
    const auto was = [&]( int p ) { return _ever[snapshot.id[p]] != 0; };

    // New points (not counted before): their area and where they started.
    double new_area = 0.0, cx = 0.0, cy = 0.0;
    double x_min = 1.0e300, x_max = -1.0e300;
    for ( const int k : counted_points )
    {
        const int p = sliding[k];
        if ( was( p ) )
            continue;
        const double v = snapshot.vol[p];
        const double x0 = _ref_x[2 * slot[p]], y0 = _ref_x[2 * slot[p] + 1];
        new_area += v;
        cx += v * x0;
        cy += v * y0;
        x_min = std::min( x_min, x0 );
        x_max = std::max( x_max, x0 );
    }
    const double dt = t - _prev_time_s;
    const double rate =
        dt > 0.0 ? new_area / dt : ( new_area > 0.0 ? 1.0e300 : 0.0 );

    // Rule (a): a counted group linked to no point counted earlier.
    bool detached = false;
    if ( !counted_points.empty() )
    {
        // Earlier counted points (still active) with the counted ones.
        std::vector<double> both_xy;
        std::vector<char> both_old;
        std::vector<char> in_counted( n, 0 );
        for ( const int k : counted_points )
        {
            both_xy.push_back( snapshot.x[2 * sliding[k]] );
            both_xy.push_back( snapshot.x[2 * sliding[k] + 1] );
            both_old.push_back( was( sliding[k] ) );
            in_counted[sliding[k]] = 1;
        }
        for ( int p = 0; p < n; ++p )
            if ( slot[p] >= 0 && was( p ) && !in_counted[p] )
            {
                both_xy.push_back( snapshot.x[2 * p] );
                both_xy.push_back( snapshot.x[2 * p + 1] );
                both_old.push_back( 1 );
            }
        if ( std::find( both_old.begin(), both_old.end(), 1 ) !=
             both_old.end() )
        {
            const std::vector<int> joint = linkedGroups( both_xy, link );
            std::vector<char> joint_old( both_old.size(), 0 );
            for ( std::size_t i = 0; i < both_old.size(); ++i )
                if ( both_old[i] )
                    joint_old[joint[i]] = 1;
            // A counted group is detached if none of its points is in a
            // joint group holding an earlier point.
            std::vector<char> linked( group_area.size(), 0 );
            for ( std::size_t i = 0; i < counted_points.size(); ++i )
                linked[label[counted_points[i]]] |= joint_old[joint[i]];
            for ( const int k : counted_points )
                detached = detached || !linked[label[k]];
        }
    }
    // Rule (b): the newly sliding area jumps after a quiet spell.
    bool jump = false;
    if ( failed() )
    {
        if ( _armed && rate >= th.jump_rate_m2_per_s )
        {
            jump = true;
            _armed = false;
            _last_high_s = t;
        }
        else if ( !_armed )
        {
            if ( rate >= 0.5 * th.jump_rate_m2_per_s )
                _last_high_s = t;
            else if ( t - _last_high_s >= th.quiet_s )
                _armed = true;
        }
    }
    std::string reason;
    if ( !failed() && !counted_points.empty() )
    {
        reason = "first failure";
        _armed = false;
        _last_high_s = t;
    }
    else if ( detached || jump )
        reason = detached && jump ? "detached group+area jump"
                 : detached       ? "detached group"
                                  : "area jump";
    if ( !reason.empty() && new_area > 0.0 )
        _onsets.push_back( { t, progress.stage_time_s, progress.stage, reason,
                             new_area, area, cx / new_area, cy / new_area,
                             x_min, x_max } );
    for ( const int k : counted_points )
        _ever[snapshot.id[sliding[k]]] = 1;

    // The sliding mass now: its area and how far it reaches beyond the
    // ground at the stage start.
    _sliding_area_m2 = area;
    double mean_dx = 0.0;
    for ( const int k : counted_points )
        mean_dx += snapshot.x[2 * sliding[k]] - _ref_x[2 * slot[sliding[k]]];
    _run_out_m = 0.0;
    for ( const int k : counted_points )
    {
        const double x = snapshot.x[2 * sliding[k]];
        const auto band =
            _outline.find( heightBand( snapshot.x[2 * sliding[k] + 1] ) );
        if ( band == _outline.end() )
            continue;
        _run_out_m =
            std::max( _run_out_m, mean_dx < 0.0 ? band->second.first - x
                                                : x - band->second.second );
    }
    _prev_time_s = t;
}

nlohmann::json FailureVerdict::json( const std::string& case_file ) const
{
    const VerdictThresholds& th = _thresholds;
    nlohmann::json onsets = nlohmann::json::array();
    for ( const SlideOnset& onset : _onsets )
        onsets.push_back(
            { { "time_s", onset.time_s },
              { "stage", onset.stage },
              { "stage_time_s", onset.stage_time_s },
              { "reason", onset.reason },
              { "new_area_m2", onset.new_area_m2 },
              { "sliding_area_m2", onset.sliding_area_m2 },
              { "initial_centroid_m", { onset.x_m, onset.y_m } },
              { "initial_x_range_m", { onset.x_min_m, onset.x_max_m } } } );
    nlohmann::json verdict = {
        { "failed", failed() },
        { "line", line( case_file ) },
        { "onsets", onsets },
        { "first_failure",
          failed() ? onsets.front() : nlohmann::json( nullptr ) },
        { "sliding_area_m2", _sliding_area_m2 },
        { "run_out_m", _run_out_m },
        { "max_displacement_m", _max_displacement_m },
        { "max_displacement_time_s", _max_displacement_time_s },
        { "max_displacement_initial_xy_m",
          { _max_displacement_x_m, _max_displacement_y_m } },
        { "snapshots_analysed", _snapshots_analysed },
        { "analysed_from_s", std::max( _first_time_s, 0.0 ) },
        { "analysed_to_s", _last_time_s },
        { "point_spacing_m", _spacing_m },
        { "definition",
          { { "analysed", "the snapshots of the dynamic stages; x_ref: the "
                          "positions at the stage start" },
            { "sliding_point",
              "active, and |x - x_ref| > disp_threshold_m with plastic shear "
              "strain > eps_threshold, or |x - x_ref| > moved_threshold_m" },
            { "sliding_group",
              "sliding points linked by neighbours closer than link_factor x "
              "point_spacing_m, counted if their area >= min_group_area_m2" },
            { "onset", "the first counted group; later, a counted group not "
                       "linked to earlier counted points, or the newly "
                       "counted area growing >= jump_rate_m2_per_s after "
                       "quiet_s below half of it" },
            { "run_out",
              "largest horizontal distance, in the sliding mass's mean "
              "horizontal direction, from a counted point to the farthest "
              "point of the stage-start state in its band of height (one "
              "point spacing); 0 within the initial outline" },
            { "disp_threshold_m", th.disp_threshold_m },
            { "eps_threshold", th.eps_threshold },
            { "moved_threshold_m", th.moved_threshold_m },
            { "link_factor", th.link_factor },
            { "min_group_area_m2", th.min_group_area_m2 },
            { "jump_rate_m2_per_s", th.jump_rate_m2_per_s },
            { "quiet_s", th.quiet_s } } } };
    if ( !failed() )
        verdict["factor_of_safety"] = "rainslide fos " + case_file;
    return verdict;
}

std::string FailureVerdict::line( const std::string& case_file ) const
{
    if ( _snapshots_analysed == 0 )
        return "not assessed: no snapshot of a dynamic stage";
    if ( !failed() )
        return format( "no failure: no sliding mass of %g m^2 in %.0f "
                       "snapshots to t = %.4g s; largest displacement %.3g m",
                       _thresholds.min_group_area_m2, _snapshots_analysed,
                       _last_time_s, _max_displacement_m ) +
               "; margin of safety: rainslide fos " + case_file;
    const SlideOnset& first = _onsets.front();
    std::string text =
        "FAILED: first slide at t = " + format( "%.4g s", first.stage_time_s ) +
        " of stage '" + first.stage + "'" +
        format( ", from x = %.1f-%.1f m, y = %.1f m", first.x_min_m,
                first.x_max_m, first.y_m ) +
        format( "; %.0f onset(s) at t =", double( _onsets.size() ) );
    for ( std::size_t i = 0; i < _onsets.size(); ++i )
        text += format( i ? ", %.4g" : " %.4g", _onsets[i].stage_time_s );
    text += format( " s; sliding area %.3g m^2, run-out %.3g m, largest "
                    "displacement %.3g m",
                    _sliding_area_m2, _run_out_m, _max_displacement_m );
    return text;
}

} // namespace mpm
