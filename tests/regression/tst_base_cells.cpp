// A base line between grid lines (the slope's): the cells it cuts get the
// stress divergence of their empty part (physics::BaseCellCompletion), so a
// column wetted onto such a base becomes hydrostatic in its bottom cell too.
#include <mpm_test_backends.hpp>
#include <mpm_test_base_cells.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
MPM_TEST_BACKEND_SUITE( BaseCells );

using namespace mpm_test::base_cells;

/*!
  The slope soil (mpm_test::slopeSoilToml) on a fixed, impermeable base
  along `polyline` (rollers on the grid's sides), a case named `name` on
  0.5 m cells; `initial` gives the body's initial p_w keys and `solver` the
  [solver] table's extra keys. The stages follow.
*/
std::string soilOnBase( const std::string& name, const std::string& cells,
                        const std::string& polygon, const std::string& polyline,
                        const std::string& initial, const std::string& solver )
{
    return "[case]\nname = \"" + name +
           "\"\nanalysis = \"unsaturated\"\n[grid]\norigin_m = [0.0, 0.0]\n"
           "cell_size_m = 0.5\ncells = " +
           cells + "\n" + mpm_test::slopeSoilToml() +
           "[[bodies]]\nmaterial = \"soil\"\npolygon_m = " + polygon + "\n" +
           initial + R"(
[[boundaries]]
where = "left"
condition = "fix_x"
[[boundaries]]
where = "right"
condition = "fix_x"
[[boundaries]]
where = "below_polyline"
condition = "fixed"
polyline_m = )" +
           polyline + "\n[solver]\ncourant_number = 0.9\n" + solver + "\n";
}

/*!
  The paper's rainfall on a body at 50 kPa suction: gravity and the suction
  held in `box` to equilibrium, then p_w = 0 held on the points of the
  surface cells for `rain_s` seconds.
*/
std::string rainfallStages( const std::string& box, const double rain_s )
{
    return R"(
[[stages]]
name = "gravity_and_suction"
type = "quasi_static"
duration_s = 20.0
reset_displacement = true
[[stages.pore_pressures]]
where = "box"
box_m = )" +
           box + R"(
pressure_pa = -50.0e3
[[stages]]
name = "rain"
type = "dynamic"
duration_s = )" +
           std::to_string( rain_s ) +
           R"(
[[stages.pore_pressures]]
where = "surface_cells"
pressure_pa = 0.0
)";
}

const char* const suction = "initial_pore_pressure_pa = -50.0e3";

/*!
  The slope soil (K = 0.044 m/s, van Genuchten) in a 5 m column one cell
  wide on a fixed, impermeable base at y = 0.3648 m, 0.73 of the way up its
  cell (the crest's base lies so in the slope), at 50 kPa suction; p_w = 0
  held on its top cell's points for 32 s: the front reaches the base at
  about 24 s.
*/
std::string columnOnCutBase( const bool completion )
{
    return soilOnBase(
               "cut_base_column", "[1, 12]",
               "[[0.0, 0.3648], [0.5, 0.3648], [0.5, 5.3648], [0.0, 5.3648]]",
               "[[0.0, 0.3648], [0.5, 0.3648]]", suction,
               std::string( "base_cell_completion = " ) +
                   ( completion ? "true" : "false" ) ) +
           rainfallStages( "[[0.0, 0.0], [0.5, 6.0]]", 32.0 );
}

//! Runs a case file text to its end and returns the last state.
template <class ExecSpace>
mpm::HostSnapshot runToEnd( const std::string& text )
{
    const auto config = mpm::parseCase( text, "case" );
    mpm::Simulation<ExecSpace> sim( config );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    return mpm::hostSnapshot( sim );
}

template <class ExecSpace>
HydrostaticCheck wetColumn( const bool completion )
{
    const auto snap = runToEnd<ExecSpace>( columnOnCutBase( completion ) );
    return checkHydrostatic( snap, heldLevel( snap ) );
}

// With the completion every cell mean lies within 0.3 % of rho_w g 5 m of
// one hydrostatic line, the pressure peak at the base is 1.03 x
// hydrostatic and the bottom cell's effective stress 1.076 x that of the
// cell above, the ratio of their depths below the top (4.971 m / 4.615 m =
// 1.077). With the empty part at the cell's mean stress and p_w: 1.8 %,
// 1.06 x and 1.1 x. On the points alone the bottom cell carried p_w 2.1 x
// and sigma'_yy 2.2 x.
TYPED_TEST( BaseCells, column_on_a_cut_base_is_hydrostatic )
{
    const HydrostaticCheck with = wetColumn<TypeParam>( true );
    std::printf( "cut-base column at 32 s: peak %.3f x hydrostatic, cell "
                 "means %.4f, sigma'_yy bottom / above %.3f\n",
                 with.peak_ratio, with.cell_mean_error, with.stress_ratio );
    EXPECT_LT( with.peak_ratio, 1.1 );
    EXPECT_LT( with.cell_mean_error, 0.01 );
    EXPECT_NEAR( with.stress_ratio, ( 5.3648 - 0.3943 ) / ( 5.3648 - 0.75 ),
                 0.005 );
    const HydrostaticCheck without = wetColumn<TypeParam>( false );
    EXPECT_GT( without.peak_ratio, 1.8 );
    EXPECT_GT( without.cell_mean_error, 0.5 );
    EXPECT_GT( without.stress_ratio, 1.8 );
}

//! Runs a wetting case with a WettingHistory and prints it.
template <class ExecSpace>
WettingHistory<ExecSpace>
wettingHistory( const std::string& text, const char* label,
                const double settled_from_s = 0.0, const double settle_s = 2.0 )
{
    auto config = mpm::parseCase( text, "case" );
    // RAINSLIDE_WETTING_COURANT_FACTOR perturbs the step (how robust the
    // checks are to the chaotic filling; see the staircase test).
    if ( const char* f = std::getenv( "RAINSLIDE_WETTING_COURANT_FACTOR" ) )
        config.solver.courant_number *= std::atof( f );
    mpm::Simulation<ExecSpace> sim( config );
    WettingHistory<ExecSpace> history( sim, settled_from_s, settle_s );
    mpm::runStages( sim, config, history );
    std::printf( "%s: front at the base %.2f s, filled %.2f s; peak p_w %.0f "
                 "Pa, %.3f x (hydrostatic + Joukowsky); %.3f x hydrostatic 1 "
                 "s before settled; settled (%d checks): points within %.4f, "
                 "cell means %.4f, intra-cell %.4f\n",
                 label, history.arrival_s, history.filled_s, history.peak_pa,
                 history.hammer_ratio, history.late_peak_ratio,
                 history.settled_checks, history.settled.point_error,
                 history.settled.cell_mean_error, history.settled.intra_cell );
    return history;
}

/*!
  Checks of a wetting history: every pulse stays within `hammer_bound` x
  its hydrostatic value plus Joukowsky's pressure, the peak is back to
  `late_peak_bound` x hydrostatic 1 s before the settled checks (unless 0),
  and in those every point lies within `point_tolerance` of rho_w g 5 m of
  one hydrostatic line, with no checkerboard inside cells (1 %, 3 x what
  the tests achieve).
*/
template <class ExecSpace>
void expectSettles( const WettingHistory<ExecSpace>& history,
                    const double point_tolerance, const int settled_checks,
                    const double late_peak_bound, const double hammer_bound )
{
    ASSERT_GT( history.arrival_s, 0.0 );
    ASSERT_GT( history.filled_s, 0.0 ) << "an unsaturated pocket remained";
    EXPECT_GT( history.settled_checks, settled_checks );
    EXPECT_LT( history.hammer_ratio, hammer_bound );
    if ( late_peak_bound > 0.0 )
    {
        EXPECT_LT( history.late_peak_ratio, late_peak_bound );
    }
    EXPECT_LT( history.settled.point_error, point_tolerance );
    EXPECT_LT( history.settled.intra_cell, 0.01 );
}

// The cut-base column, every 0.05 s: the front fills the base at 23.75 s,
// the inflowing water stops and p_w peaks at 107 kPa (0.81 x hydrostatic
// plus Joukowsky) and is back to 1.03 x hydrostatic within 1 s. From 2 s
// later every point lies within 0.53 % of rho_w g 5 m of one hydrostatic
// line, 0.3 % inside cells. With the empty part at the cut cell's mean
// p_w (before the weight gradients) the cut cell's points sat 1.4 kPa
// above the line (2.85 %).
TYPED_TEST( BaseCells, column_on_a_cut_base_settles_hydrostatic_point_by_point )
{
    const auto history =
        wettingHistory<TypeParam>( columnOnCutBase( true ), "cut-base column" );
    expectSettles( history, 0.016, 100, 1.1, 1.2 );
}

/*!
  A layer of the slope soil on a fixed, impermeable base inclined at 10
  degrees (y = 3.4648 - 0.182 x, a staircase of fixed nodes on the 0.5 m
  grid, as under the slope), 14 m wide with rollers at both ends and a
  horizontal top at y = 6 m: saturated, p_w hydrostatic from the top, then
  left to itself under gravity for 4 s. `solver` is the [solver] table.
*/
std::string layerOnStaircase( const std::string& solver )
{
    return soilOnBase(
               "staircase_layer", "[28, 14]",
               "[[0.0, 3.4648], [14.0, 0.9164], [14.0, 6.0], [0.0, 6.0]]",
               "[[0.0, 3.4648], [14.0, 0.9164]]",
               "initial_pore_pressure_pa = 58860.0\n"
               "initial_pore_pressure_gradient_pa_per_m = -9810.0",
               solver ) +
           R"(
[[stages]]
name = "settle"
type = "dynamic"
duration_s = 4.0
)";
}

// Hydrostatic with the cut cells completed and the slivers of soil no
// point represents fixed: the largest p_w 0.998 x hydrostatic, cell means
// within 0.34 % of rho_w g 5 m of one hydrostatic line, 0.08 % inside
// cells. With the empty parts at their cell's mean stress and p_w (no
// weight gradients) the cut cells' means were 3.1 % off (their p_w that of
// the whole cell's centre, below their points). Before (points only,
// 226a27a), a node above a sliver rested on nothing, its water fell into
// the base and the layer circulated at 0.3 m/s, with p_w up to 2.4 x
// hydrostatic.
TYPED_TEST( BaseCells, saturated_layer_on_a_staircase_base_stays_hydrostatic )
{
    const auto snap = runToEnd<TypeParam>( layerOnStaircase( "" ) );
    const HydrostaticCheck with = checkHydrostatic( snap, 6.0 );
    std::printf( "staircase layer: peak %.3f, cell means %.4f, intra-cell "
                 "%.4f\n",
                 with.peak_ratio, with.cell_mean_error, with.intra_cell );
    EXPECT_LT( with.peak_ratio, 1.03 );
    EXPECT_LT( with.cell_mean_error, 0.01 );
    EXPECT_LT( with.intra_cell, 0.003 );
    const auto before = runToEnd<TypeParam>( layerOnStaircase(
        "base_cell_completion = false\ncell_equilibrium = false\n" ) );
    const HydrostaticCheck without = checkHydrostatic( before, 6.0 );
    EXPECT_GT( without.peak_ratio, 1.5 );
}

/*!
  The same soil 2.5-3.6 m thick on a 10-degree staircase base (6 m wide),
  at 50 kPa suction, p_w = 0 held on its top cell's points: the front
  reaches the base after about 12 s; 20 s in all.
*/
std::string wettingOntoStaircase()
{
    return soilOnBase( "staircase_wetting", "[12, 10]",
                       "[[0.0, 2.0], [6.0, 0.942], [6.0, 4.5], [0.0, 4.5]]",
                       "[[0.0, 2.0], [6.0, 0.942]]", suction, "" ) +
           rainfallStages( "[[0.0, 0.0], [6.0, 5.0]]", 21.0 );
}

// Wetted onto the 10-degree staircase (2-D, a base that is not
// grid-aligned): the front fills the base at 12.6 s, the last pocket at
// 15.15 s, p_w peaks at 231 kPa (1.37 x hydrostatic plus Joukowsky); from
// 0.5 s after the filling every point within 0.50 % of rho_w g 5 m of one
// hydrostatic line, 0.3 % inside cells, cell means within 0.3 % (2.8 % with
// the empty parts at their cell's mean). Point-wise (226a27a) the front's
// arrival left p_w up to 3.2 x hydrostatic and points of one cell 74 %
// apart (RMS, relative to hydrostatic). The filling of the last pockets
// above the staircase is chaotic: Courant numbers 1e-6 to 1e-4 apart, or
// Eq. 8 solved to 1e-9 Pa instead of exactly, gave arrivals from 12.6 to
// 14.15 s, the last pocket filled up to 18.2 s (RAINSLIDE_WETTING_COURANT_
// FACTOR = 0.99999), peaks of 66 to 208 kPa and single-snapshot pulses 1 s
// before the settled checks of 1.03 to 1.98 x hydrostatic, all within the
// Joukowsky bound (0.50-1.15); so that time's peak is not asserted here
// (the 1-D column's, 1.03 under the same perturbations, is), and the
// settled checks start once the layer has filled for good: in one run a
// pocket rose above -2 % of rho_w g 5 m at 16.4 s, sank to -2.7 kPa and
// drained until 18.4 s; by 18.75 s every point was within 0.5 % again
// (on 2 threads: filled at 15.9 s, peak 116 kPa, 0.67). The rain runs 21 s
// so that a second of settled checks follows such a late filling. The
// filling pulse is as chaotic: over 14 Courant numbers 1e-5 to 4e-3 apart
// it ranged 0.36-1.57 x (hydrostatic plus Joukowsky) with constant moduli
// and 0.44-1.37 x with moduli falling with dilation (the default; 1.37 x,
// 231 kPa, unperturbed), so it is bounded at 2 x here.
TYPED_TEST( BaseCells, layer_wetted_onto_a_staircase_settles_hydrostatic )
{
    const auto history = wettingHistory<TypeParam>( wettingOntoStaircase(),
                                                    "staircase wetting", 17.0 );
    expectSettles( history, 0.016, 20, 0.0, 2.0 );
    EXPECT_LT( history.settled.cell_mean_error, 0.01 );
}

} // namespace
