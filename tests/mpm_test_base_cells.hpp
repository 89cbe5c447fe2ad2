#ifndef MPM_TEST_BASE_CELLS_HPP
#define MPM_TEST_BASE_CELLS_HPP

// Helpers of the base-cell regression tests (regression/tst_base_cells.cpp):
// p_w of the points against a hydrostatic line, Joukowsky's pressure and
// the history of a wetting run.
#include <physics/mpm_wave_speeds.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace mpm_test
{
namespace base_cells
{
//! p_w of the points against a hydrostatic line, from a snapshot.
struct HydrostaticCheck
{
    double peak_ratio;      //!< largest p_w / rho_w g (y_ref - lowest y)
    double cell_mean_error; //!< largest deviation of a cell mean from one
                            //!< hydrostatic line, / (rho_w g 5 m)
    double intra_cell;      //!< RMS over the points (not held) of their
                            //!< deviation from hydrostatic less their
                            //!< cell's mean deviation, over the RMS
                            //!< hydrostatic p_w (a checkerboard)
    double point_error;     //!< largest deviation of a point from the
                            //!< cell means' line, / (rho_w g 5 m)
    double stress_ratio;    //!< column only: sigma'_yy bottom / next cell
};

/*!
  Compares the points' p_w with rho_w g (y_ref - y), y_ref the mean height
  of the held (p_w = 0) points: the cell means with one line (their median
  offset: the p_w = 0 band is a cell thick, so the discrete water table
  sits up to h/4 above the held points), the peak and the spread inside
  cells (cells of h = 0.5 m).
*/
inline HydrostaticCheck checkHydrostatic( const mpm::HostSnapshot& snap,
                                          const double y_ref )
{
    const double rho_g = 1000.0 * 9.81;
    const double h = 0.5;
    const int n = static_cast<int>( snap.p_w.size() );
    double y_min = 1e9, p_max = 0.0;
    // Per cell: sum p_w, sum y, sum sigma'_yy, count, and of the deviation
    // from hydrostatic r: sum r, sum r^2.
    std::map<std::pair<int, int>, std::array<double, 6>> cells;
    for ( int p = 0; p < n; ++p )
    {
        const double y = snap.x[2 * p + 1];
        y_min = std::min( y_min, y );
        p_max = std::max( p_max, snap.p_w[p] );
        if ( snap.p_w[p] == 0.0 )
            continue;
        auto& c = cells[{ static_cast<int>( std::floor( snap.x[2 * p] / h ) ),
                          static_cast<int>( std::floor( y / h ) ) }];
        c[0] += snap.p_w[p];
        c[1] += y;
        c[2] += snap.sigma[4 * p + 1];
        c[3] += 1.0;
        const double r = snap.p_w[p] - rho_g * ( y_ref - y );
        c[4] += r;
        c[5] += r * r;
    }
    HydrostaticCheck r{ p_max / ( rho_g * ( y_ref - y_min ) ), 0.0, 0.0, 0.0,
                        0.0 };
    std::vector<double> offsets;
    double spread2 = 0.0, reference2 = 0.0;
    for ( const auto& [key, c] : cells )
    {
        const double mean = c[0] / c[3];
        const double hydrostatic = rho_g * ( y_ref - c[1] / c[3] );
        offsets.push_back( mean - hydrostatic );
        spread2 += c[5] - c[4] * c[4] / c[3];
        reference2 += c[3] * hydrostatic * hydrostatic;
    }
    std::vector<double> sorted = offsets;
    std::sort( sorted.begin(), sorted.end() );
    const double level = sorted[sorted.size() / 2];
    for ( const double offset : offsets )
        r.cell_mean_error = std::max(
            r.cell_mean_error, std::abs( offset - level ) / ( rho_g * 5.0 ) );
    r.intra_cell = std::sqrt( std::max( spread2, 0.0 ) / reference2 );
    for ( int p = 0; p < n; ++p )
        if ( snap.p_w[p] != 0.0 )
            r.point_error = std::max(
                r.point_error,
                std::abs( snap.p_w[p] - rho_g * ( y_ref - snap.x[2 * p + 1] ) -
                          level ) /
                    ( rho_g * 5.0 ) );
    const auto bottom = cells.begin()->second;
    const auto above = std::next( cells.begin() )->second;
    r.stress_ratio = ( bottom[2] / bottom[3] ) / ( above[2] / above[3] );
    return r;
}

//! Mean height of the points whose p_w is exactly 0 (the held ones), m.
inline double heldLevel( const mpm::HostSnapshot& snap )
{
    double sum = 0.0;
    int count = 0;
    for ( std::size_t p = 0; p < snap.p_w.size(); ++p )
        if ( snap.p_w[p] == 0.0 )
        {
            sum += snap.x[2 * p + 1];
            ++count;
        }
    EXPECT_GT( count, 0 );
    return count ? sum / count : 0.0;
}

/*!
  Joukowsky's pressure of the seepage stopped at once, Pa: the undrained
  wave speed of the saturated slope soil (physics::twoPhaseWaveSpeed:
  E_c = 14.8 MPa, n = 0.3, K_w = 2.2 GPa, rho_m = 2190 kg/m^3, 1830 m/s)
  times the seepage momentum rho_w n S |w|. The model has no gas phase (as
  the paper's): when the last unsaturated pores at an impermeable base
  fill, the inflowing water stops within a step and sends this pulse.
*/
inline double joukowsky( const double seepage_momentum )
{
    const double nu = 0.33, E = 1.0e7, n = 0.3;
    const double E_c = E * ( 1.0 - nu ) / ( ( 1.0 + nu ) * ( 1.0 - 2.0 * nu ) );
    const double c = mpm::physics::twoPhaseWaveSpeed(
        E_c, ( 1.0 - n ) * 2700.0 + n * 1000.0, 1000.0, n, 1.0, 0.0, 2.2e9 );
    return c * seepage_momentum;
}

/*!
  The rain stage of a wetting case every 0.05 s: the time the front
  reaches the base (the lowest point's p_w first >= 0); the largest p_w
  over the stage, and over its hydrostatic value plus Joukowsky's pressure
  of the largest seepage momentum rho_w n S |v_w - v_s| of a point in the
  last 0.25 s (hammer_ratio); the time the layer has filled for good
  (filled_s: from then to the stage end no point lies below -2 % of
  rho_w g 5 m, an unsaturated pocket; a pocket can linger just below that
  and drain over a second or more, so the first time no point does is not
  enough); the peak ratio from 1 s before the settled checks, which run
  from `settle_s` after the arrival and 0.5 s after the filling (and not
  before `settled_from_s`) to the end. The checks are kept and summed up
  at the rain stage's end.
*/
template <class ExecSpace>
class WettingHistory : public mpm::RunObserver
{
  public:
    WettingHistory( const mpm::Simulation<ExecSpace>& sim,
                    const double settled_from_s, const double settle_s )
        : _sim( sim )
        , _settled_from( settled_from_s )
        , _settle( settle_s )
    {
    }
    void onStep( const mpm::RunProgress& progress ) override
    {
        if ( progress.stage != "rain" || progress.stage_time_s < _next )
            return;
        _next += 0.05;
        const auto snap = mpm::hostSnapshot( _sim );
        const HydrostaticCheck check =
            checkHydrostatic( snap, heldLevel( snap ) );
        double lowest_y = 1e9, lowest_p = 0.0, momentum = 0.0, p_max = 0.0,
               p_min = 0.0;
        for ( int p = 0; p < snap.num_points; ++p )
        {
            if ( snap.x[2 * p + 1] < lowest_y )
            {
                lowest_y = snap.x[2 * p + 1];
                lowest_p = snap.p_w[p];
            }
            p_max = std::max( p_max, snap.p_w[p] );
            p_min = std::min( p_min, snap.p_w[p] );
            momentum = std::max(
                momentum,
                1000.0 * snap.n[p] * snap.S[p] *
                    std::hypot( snap.v_w[2 * p] - snap.v[2 * p],
                                snap.v_w[2 * p + 1] - snap.v[2 * p + 1] ) );
        }
        for ( int k = 4; k > 0; --k )
            _momenta[k] = _momenta[k - 1];
        _momenta[0] = momentum;
        const double recent = *std::max_element( _momenta, _momenta + 5 );
        peak_pa = std::max( peak_pa, p_max );
        if ( check.peak_ratio > 0.0 )
            hammer_ratio =
                std::max( hammer_ratio, p_max / ( p_max / check.peak_ratio +
                                                  joukowsky( recent ) ) );
        if ( arrival_s < 0.0 && lowest_p >= 0.0 )
            arrival_s = progress.stage_time_s;
        if ( arrival_s >= 0.0 )
            _checks.push_back( { progress.stage_time_s, p_min, check } );
    }
    void onStageEnd( const mpm::RunProgress& progress,
                     const mpm::StageSummary& ) override
    {
        if ( progress.stage != "rain" )
            return;
        const double pocket = -0.02 * 1000.0 * 9.81 * 5.0;
        for ( const Check& c : _checks )
            if ( c.p_min < pocket )
                filled_s = -1.0;
            else if ( filled_s < 0.0 )
                filled_s = c.time_s;
        if ( filled_s < 0.0 )
            return;
        const double settled_from =
            std::max( { arrival_s + _settle, filled_s + 0.5, _settled_from } );
        for ( const Check& c : _checks )
        {
            if ( c.time_s >= settled_from - 1.0 )
                late_peak_ratio =
                    std::max( late_peak_ratio, c.hydrostatic.peak_ratio );
            if ( c.time_s < settled_from )
                continue;
            ++settled_checks;
            settled.point_error =
                std::max( settled.point_error, c.hydrostatic.point_error );
            settled.intra_cell =
                std::max( settled.intra_cell, c.hydrostatic.intra_cell );
            settled.cell_mean_error = std::max( settled.cell_mean_error,
                                                c.hydrostatic.cell_mean_error );
        }
    }
    double arrival_s = -1.0;
    double filled_s = -1.0;
    double peak_pa = 0.0;
    double hammer_ratio = 0.0;
    double late_peak_ratio = 0.0;
    int settled_checks = 0;
    HydrostaticCheck settled{ 0.0, 0.0, 0.0, 0.0, 0.0 };

  private:
    const mpm::Simulation<ExecSpace>& _sim;
    double _settled_from;
    double _settle;
    double _next = 0.0;
    double _momenta[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
    //! A check from the front's arrival on.
    struct Check
    {
        double time_s;
        double p_min; //!< lowest p_w, Pa
        HydrostaticCheck hydrostatic;
    };
    std::vector<Check> _checks;
};

} // namespace base_cells
} // namespace mpm_test

#endif // MPM_TEST_BASE_CELLS_HPP
