#ifndef MPM_STATIC_STOP_HPP
#define MPM_STATIC_STOP_HPP

#include <case/mpm_case_config.hpp>
#include <records/mpm_stage_state.hpp>
#include <solver/output/mpm_run_observer.hpp>

#include <mpm_device_type.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief How many of `active` points may be as fast as the static speed or
  faster while the `percentile`-th percentile of their speeds is below it:
  floor(N (100 - p) / 100). With the nearest-rank percentile (the value of
  rank ceil(p N / 100) among the N speeds in ascending order) "percentile
  below v" holds exactly when at most that many points are >= v, so a count
  decides it without a sort. 0 for p = 100 (every point below).
*/
inline long allowedPointsNotBelow( const long active, const double percentile )
{
    const double allowed = active * ( 100.0 - percentile ) / 100.0;
    // Round-off of the product must not drop a whole point.
    return std::max( 0L, static_cast<long>( std::floor(
                             allowed + 1.0e-9 * ( 1.0 + allowed ) ) ) );
}

//---------------------------------------------------------------------------//
/*!
  \brief Static stop of a dynamic stage: updates the state and returns true
  once the stage should end (a slide, then the speed statistic below the
  static speed for the window). still() tells whether the statistic is
  below the static speed this step; maxDisplacement() gives the largest
  point displacement. Each is called only when needed: maxDisplacement()
  until a slide has been seen, still() after it.
*/
template <class Still, class MaxDisplacement>
bool staticAgainIf( const StaticStop& stop, Still&& still,
                    const double stage_time_s,
                    MaxDisplacement&& maxDisplacement, StageLoopState& state )
{
    if ( !state.has_moved && maxDisplacement() > stop.slide_displacement_m )
        state.has_moved = true;
    if ( !state.has_moved || !still() )
    {
        state.static_since = -1.0;
        return false;
    }
    if ( state.static_since < 0.0 )
        state.static_since = stage_time_s;
    return stage_time_s - state.static_since >= stop.window_s;
}

//! staticAgainIf with the largest point speed of the step as the statistic
//! (speed_percentile = 100).
template <class MaxDisplacement>
bool staticAgain( const StaticStop& stop, const double max_speed,
                  const double stage_time_s, MaxDisplacement&& maxDisplacement,
                  StageLoopState& state )
{
    return staticAgainIf(
        stop, [&]() { return max_speed < stop.static_speed_m_per_s; },
        stage_time_s, maxDisplacement, state );
}

//---------------------------------------------------------------------------//
/*!
  \brief Whether the static stop's speed statistic is below its static
  speed on `sim` this step. speed_percentile = 100 uses the step's largest
  point speed `max_speed` (no further reduction: the default costs what it
  did); below 100 one reduction on the device counts the points at or above
  the static speed (Simulation::pointsNotBelowSpeed) against
  allowedPointsNotBelow of the `active` points.
*/
template <class Sim>
bool speedStatisticBelow( const Sim& sim, const StaticStop& stop,
                          const double max_speed, const long active )
{
    if ( stop.speed_percentile >= 100.0 )
        return max_speed < stop.static_speed_m_per_s;
    return sim.pointsNotBelowSpeed( stop.static_speed_m_per_s ) <=
           allowedPointsNotBelow( active, stop.speed_percentile );
}

//---------------------------------------------------------------------------//
/*!
  \brief Writes the static stop's statistic at the stage end into the
  stage summary, from the stage's last snapshot: the percentile it watches,
  the static speed, the nearest-rank speed_percentile-th percentile of the
  active points' speeds, how many points were at or above the static speed
  and how many may be.
*/
inline void recordSpeedStatistic( const StaticStop& stop,
                                  const HostSnapshot& snapshot,
                                  StageSummary& summary )
{
    std::vector<double> speeds;
    for ( int p = 0; p < snapshot.num_points; ++p )
        if ( snapshot.status[p] == point_active )
            speeds.push_back(
                std::hypot( snapshot.v[2 * p], snapshot.v[2 * p + 1] ) );
    const long active = static_cast<long>( speeds.size() );
    const long allowed = allowedPointsNotBelow( active, stop.speed_percentile );
    summary.speed_percentile = stop.speed_percentile;
    summary.static_speed_m_per_s = stop.static_speed_m_per_s;
    summary.allowed_points_not_below = allowed;
    summary.points_not_below_static_speed = static_cast<long>(
        std::count_if( speeds.begin(), speeds.end(),
                       [&]( const double v )
                       { return !( v < stop.static_speed_m_per_s ); } ) );
    summary.speed_at_percentile_m_per_s = 0.0;
    if ( active > allowed )
    {
        // The value of rank N - allowed (1-based) in ascending order.
        const auto rank = speeds.begin() + ( active - allowed - 1 );
        std::nth_element( speeds.begin(), rank, speeds.end() );
        summary.speed_at_percentile_m_per_s = *rank;
    }
}

} // namespace mpm

#endif // MPM_STATIC_STOP_HPP
