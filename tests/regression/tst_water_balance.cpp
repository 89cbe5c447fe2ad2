// The water balance of metrics.json (physics::WaterBalance): every term
// against what the case prescribes, and the closure of the stored water.
#include <mpm_test_backends.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
template <class ExecSpace>
class WaterBalance : public ::testing::Test
{
};
TYPED_TEST_SUITE( WaterBalance, mpm_test::Backends, mpm_test::BackendName );

constexpr double width = 0.2;  // m, two cells
constexpr double height = 1.0; // m, ten cells
constexpr double rho_w_g = 1000.0 * 9.81;
constexpr double K_s = 4.5e-9 * rho_w_g / 1.0e-3; // 0.0441 m/s

/*!
  A column of Gardner soil (alpha 4 /m, the slope soil's k and porosity,
  stiff) filling a grid two cells wide, `height` high, that starts at a
  uniform p_w of `p_w0` (out of equilibrium under gravity) and runs one
  dynamic stage of `duration` s: rollers on the sides, a fixed base
  (`base_hydraulic`), every grid edge impermeable unless said; `stage`
  adds the stage's conditions (inflows, pore pressures).
*/
std::string column( const double p_w0, const std::string& base_hydraulic,
                    const double duration, const std::string& stage )
{
    const std::string grid = R"([case]
name = "water_balance"
analysis = "unsaturated"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.1
cells = [2, 10]
)";
    char body[512];
    std::snprintf( body, sizeof body, R"([[bodies]]
material = "soil"
polygon_m = [[0.0, 0.0], [%.17g, 0.0], [%.17g, %.17g], [0.0, %.17g]]
initial_pore_pressure_pa = %.17g
[[boundaries]]
where = "bottom"
condition = "fixed"
hydraulic = "%s"
[[stages]]
name = "flow"
type = "dynamic"
duration_s = %.17g
)",
                   width, width, height, height, p_w0, base_hydraulic.c_str(),
                   duration );
    const std::string text = grid + mpm_test::gardnerSoilOnRollersToml() + body;
    return text + stage;
}

//! Runs `toml` and returns its summary (the run's water balance).
template <class ExecSpace>
mpm::RunSummary run( const std::string& toml )
{
    const auto config = mpm::parseCase( toml, "water_balance" );
    mpm::Simulation<ExecSpace> sim( config );
    mpm::RunObserver observer;
    return mpm::runStages( sim, config, observer );
}

void print( const char* what, const mpm::physics::WaterBalance& w )
{
    std::printf( "Water balance, %s: stored %.6e -> %.6e m3/m, point inflow "
                 "%.6e, runoff %.6e, prescribed %.6e, flow in %.6e, closure "
                 "%.3e (relative %.3e)\n",
                 what, w.stored_start, w.stored_end, w.point_inflow, w.runoff,
                 w.prescribed, w.flow_in, w.closureError(),
                 w.relativeClosureError() );
}

//---------------------------------------------------------------------------//
// Water that only moves inside a sealed column stays there: no term but the
// seepage between points, whose sum over the column is the flow across its
// impermeable edges, zero.
TYPED_TEST( WaterBalance, sealed_column_keeps_its_water )
{
    const auto summary =
        run<TypeParam>( column( -5000.0, "impermeable", 1.0, "" ) );
    const auto& w = summary.water;
    print( "sealed column", w );
    EXPECT_GT( w.stored_start, 0.0 );
    EXPECT_EQ( w.point_inflow, 0.0 );
    EXPECT_EQ( w.runoff, 0.0 );
    EXPECT_EQ( w.prescribed, 0.0 );
    // The points' quadrature of the seepage divergence is not exactly
    // conservative once they move: 1.9e-5 of the water while it settles.
    EXPECT_LT( std::fabs( w.flow_in ), 6.0e-5 * w.stored_start );
    EXPECT_LT( std::fabs( w.closureError() ), 2.0e-7 * w.stored_start );
}

// Rain twice the soil's conductivity on the top cells' points of a column
// on a drained base: the inflow is what the case prescribes, the soil takes
// what it can and the rest runs off; the stored water closes the balance.
TYPED_TEST( WaterBalance, rain_is_taken_in_or_runs_off )
{
    const double duration = 1.0;
    const double flux = 2.0 * K_s;
    char inflow[256];
    std::snprintf( inflow, sizeof inflow,
                   "[[stages.inflows]]\nwhere = \"surface_cells\"\n"
                   "flux_m_per_s = %.17g\nlength_m = %.17g\n",
                   flux, width );
    const auto summary =
        run<TypeParam>( column( -5000.0, "drained", duration, inflow ) );
    const auto& w = summary.water;
    print( "rain on points", w );
    EXPECT_LT(
        mpm_test::relativeDifference( w.point_inflow, flux * width * duration ),
        1.0e-12 );
    EXPECT_GT( w.runoff, 0.05 * w.point_inflow );
    EXPECT_LT( w.runoff, w.point_inflow );
    EXPECT_LT( w.relativeClosureError(), 4.0e-6 );
}

// The top cells' points held at p_w = 0 on a sealed column (the slope's
// surface condition): the held points supply all the water that enters.
TYPED_TEST( WaterBalance, held_surface_points_supply_the_water )
{
    const std::string held = "[[stages.pore_pressures]]\n"
                             "where = \"surface_cells\"\npressure_pa = 0.0\n";
    const auto summary =
        run<TypeParam>( column( -5000.0, "impermeable", 1.0, held ) );
    const auto& w = summary.water;
    print( "held surface", w );
    EXPECT_GT( w.prescribed, 1.0 * w.stored_start );
    EXPECT_LT( std::fabs( w.flow_in ), 3.0e-4 * w.stored_start );
    EXPECT_LT( w.relativeClosureError(), 3.0e-6 );
}

// Rain as a flux boundary on the top edge of a column on a sealed base:
// all of it enters as seepage through the edge.
TYPED_TEST( WaterBalance, edge_inflow_enters_as_seepage )
{
    const double duration = 1.0;
    const double flux = 0.5 * K_s;
    char inflow[128];
    std::snprintf( inflow, sizeof inflow,
                   "[[stages.inflows]]\nwhere = \"top\"\n"
                   "flux_m_per_s = %.17g\n",
                   flux );
    const auto summary =
        run<TypeParam>( column( -5000.0, "impermeable", duration, inflow ) );
    const auto& w = summary.water;
    print( "edge inflow", w );
    EXPECT_LT(
        mpm_test::relativeDifference( w.flow_in, flux * width * duration ),
        3.0e-4 );
    EXPECT_LT( w.relativeClosureError(), 6.0e-6 );
}

} // namespace
