// A base line between grid lines (the slope's): the cells it cuts get the
// stress divergence of their empty part (physics::BaseCellCompletion), so a
// column wetted onto such a base becomes hydrostatic in its bottom cell too.
#include <mpm_test_backends.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <physics/mpm_base_cell.hpp>
#include <solver/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace
{
template <class ExecSpace>
class BaseCells : public ::testing::Test
{
};
TYPED_TEST_SUITE( BaseCells, mpm_test::Backends, mpm_test::BackendName );

// A full cell of 2 x 2 Gauss points misses nothing; one row of points
// (the soil above a base through the cell) misses the lower half.
TEST( BaseCellCompletion, missing_area_integral )
{
    const double h = 0.5;
    const mpm::physics::BaseCellCompletion completion{ h };
    const double g[2] = { 0.5 - 0.5 / std::sqrt( 3.0 ),
                          0.5 + 0.5 / std::sqrt( 3.0 ) };
    const double v = 0.25 * h * h;
    for ( int k = 0; k < 4; ++k )
    {
        double D[2];
        completion.missing( k, 4 * v, 2 * v * ( g[0] + g[1] ),
                            2 * v * ( g[0] + g[1] ), D );
        EXPECT_NEAR( D[0], 0.0, 1e-15 );
        EXPECT_NEAR( D[1], 0.0, 1e-15 );
        // The upper row only (eta = g[1]): the top corners miss h/4 of the
        // full cell's int dN/dy = h/2; the bottom corners -h/4.
        completion.missing( k, 2 * v, v * ( g[0] + g[1] ), 2 * v * g[1], D );
        EXPECT_NEAR( D[1], ( k >> 1 ) ? 0.25 * h : -0.25 * h, 1e-15 ) << k;
    }
    // A uniform pore pressure: the water force of the missing part is p D.
    double D[2] = { 0.1, 0.2 }, f[2];
    completion.waterForce( D, 1.0e4, f );
    EXPECT_DOUBLE_EQ( f[1], 2.0e3 );
    const double sigma[3] = { -1.0, -2.0, 0.0 };
    completion.mixtureForce( D, sigma, f );
    EXPECT_DOUBLE_EQ( f[1], 0.4 );
}

/*!
  The slope soil (K = 0.044 m/s, van Genuchten) in a 5 m column one cell
  wide on a fixed, impermeable base at y = 0.3648 m, 0.73 of the way up its
  cell (the crest's base lies so in the slope), at 50 kPa suction; p_w = 0
  held on its top cell's points for 32 s: the front reaches the base at
  about 24 s.
*/
std::string columnOnCutBase( const bool completion )
{
    return std::string( R"(
[case]
name = "cut_base_column"
analysis = "unsaturated"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.5
cells = [1, 12]
)" ) + mpm_test::slopeSoilToml() +
           R"(
[[bodies]]
material = "soil"
polygon_m = [[0.0, 0.3648], [0.5, 0.3648], [0.5, 5.3648], [0.0, 5.3648]]
initial_pore_pressure_pa = -50.0e3
[[boundaries]]
where = "left"
condition = "fix_x"
[[boundaries]]
where = "right"
condition = "fix_x"
[[boundaries]]
where = "below_polyline"
condition = "fixed"
polyline_m = [[0.0, 0.3648], [0.5, 0.3648]]
[solver]
courant_number = 0.9
base_cell_completion = )" +
           ( completion ? "true" : "false" ) + R"(
[[stages]]
name = "gravity_and_suction"
type = "quasi_static"
duration_s = 20.0
reset_displacement = true
[[stages.pore_pressures]]
where = "box"
box_m = [[0.0, 0.0], [0.5, 6.0]]
pressure_pa = -50.0e3
[[stages]]
name = "rain"
type = "dynamic"
duration_s = 32.0
[[stages.pore_pressures]]
where = "surface_cells"
pressure_pa = 0.0
)";
}

struct ColumnResult
{
    double peak_ratio;      //!< largest p_w / hydrostatic at the base
    double cell_mean_error; //!< largest deviation of a cell mean from one
                            //!< hydrostatic line, / (rho_w g 5 m)
    double stress_ratio;    //!< sigma'_yy bottom cell / cell above
};

template <class ExecSpace>
ColumnResult wetColumn( const bool completion )
{
    const auto config =
        mpm::parseCase( columnOnCutBase( completion ), "column" );
    mpm::Simulation<ExecSpace> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const auto snap = mpm::hostSnapshot( sim );
    const double rho_g = 1000.0 * 9.81;
    const int n = static_cast<int>( snap.p_w.size() );
    // Reference level: the mean height of the held (p_w = 0) points.
    double y_sum = 0.0, y_min = 1e9;
    int held = 0;
    for ( int p = 0; p < n; ++p )
    {
        y_min = std::min( y_min, snap.x[2 * p + 1] );
        if ( snap.p_w[p] == 0.0 )
        {
            y_sum += snap.x[2 * p + 1];
            ++held;
        }
    }
    EXPECT_GT( held, 0 );
    const double y_ref = y_sum / held;
    // Cell means of p_w, y and sigma'_yy of the points that are not held.
    std::map<int, std::array<double, 4>> cells;
    double p_max = 0.0;
    for ( int p = 0; p < n; ++p )
    {
        p_max = std::max( p_max, snap.p_w[p] );
        if ( snap.p_w[p] == 0.0 )
            continue;
        auto& c =
            cells[static_cast<int>( std::floor( snap.x[2 * p + 1] / 0.5 ) )];
        c[0] += snap.p_w[p];
        c[1] += snap.x[2 * p + 1];
        c[2] += snap.sigma[4 * p + 1];
        c[3] += 1.0;
    }
    ColumnResult r{ p_max / ( rho_g * ( y_ref - y_min ) ), 0.0, 0.0 };
    // Each cell mean's offset from rho_w g (depth below the held points):
    // one level for all (the p_w = 0 band is a cell thick, so the discrete
    // water table sits up to h/4 above the held points) means hydrostatic.
    std::vector<double> offsets;
    for ( const auto& [j, c] : cells )
        offsets.push_back( c[0] / c[3] - rho_g * ( y_ref - c[1] / c[3] ) );
    std::vector<double> sorted = offsets;
    std::sort( sorted.begin(), sorted.end() );
    const double level = sorted[sorted.size() / 2];
    for ( const double offset : offsets )
        r.cell_mean_error = std::max(
            r.cell_mean_error, std::abs( offset - level ) / ( rho_g * 5.0 ) );
    const auto bottom = cells.begin()->second;
    const auto above = std::next( cells.begin() )->second;
    r.stress_ratio = ( bottom[2] / bottom[3] ) / ( above[2] / above[3] );
    return r;
}

// With the completion every cell mean lies within 1.8 % of rho_w g 5 m of
// one hydrostatic line (the bottom cell's; the others within 0.3 %), the
// pressure peak at the base is 1.05 x hydrostatic and the bottom cell's
// effective stress 1.1 x that of the cell above (0.2 m higher). On the
// points alone the bottom cell carried p_w 2.1 x and sigma'_yy 2.2 x.
TYPED_TEST( BaseCells, column_on_a_cut_base_is_hydrostatic )
{
    const ColumnResult with = wetColumn<TypeParam>( true );
    EXPECT_LT( with.peak_ratio, 1.15 );
    EXPECT_LT( with.cell_mean_error, 0.05 );
    EXPECT_LT( with.stress_ratio, 1.3 );
    const ColumnResult without = wetColumn<TypeParam>( false );
    EXPECT_GT( without.peak_ratio, 1.8 );
    EXPECT_GT( without.cell_mean_error, 0.5 );
    EXPECT_GT( without.stress_ratio, 1.8 );
}

} // namespace
