// The water balance of metrics.json (physics::WaterBalance): every term
// against what the case prescribes, and the closure of the stored water.
#include <mpm_test_backends.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
MPM_TEST_BACKEND_SUITE( WaterBalance );

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
    using namespace mpm_test;
    return caseToml( "water_balance", "unsaturated" ) +
           gridToml( "0.1", "[2, 10]" ) + gardnerSoilOnRollersToml() +
           soilBodyToml(
               rectangleToml( tomlNumber( width ), tomlNumber( height ) ) ) +
           "initial_pore_pressure_pa = " + tomlNumber( p_w0 ) + "\n" +
           boundaryToml( "bottom", "fixed" ) +
           tomlString( "hydraulic", base_hydraulic ) +
           stageToml( "flow", "dynamic", tomlNumber( duration ) ) + stage;
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

//! The water balance of a run of `toml`, printed as `what`.
template <class ExecSpace>
mpm::physics::WaterBalance balanceOf( const char* what,
                                      const std::string& toml )
{
    const mpm::physics::WaterBalance water = run<ExecSpace>( toml ).water;
    print( what, water );
    return water;
}

//! [[stages.inflows]] of `flux` on `where`.
std::string inflowToml( const std::string& where, const double flux )
{
    return "[[stages.inflows]]\n" + mpm_test::tomlString( "where", where ) +
           "flux_m_per_s = " + mpm_test::tomlNumber( flux ) + "\n";
}

//---------------------------------------------------------------------------//
// Water that only moves inside a sealed column stays there: no term but the
// seepage between points, whose sum over the column is the flow across its
// impermeable edges, zero.
TYPED_TEST( WaterBalance, sealed_column_keeps_its_water )
{
    const auto w = balanceOf<TypeParam>(
        "sealed column", column( -5000.0, "impermeable", 1.0, "" ) );
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
    const std::string inflow = inflowToml( "surface_cells", flux ) +
                               "length_m = " + mpm_test::tomlNumber( width ) +
                               "\n";
    const auto w = balanceOf<TypeParam>(
        "rain on points", column( -5000.0, "drained", duration, inflow ) );
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
    const auto w = balanceOf<TypeParam>(
        "held surface", column( -5000.0, "impermeable", 1.0, held ) );
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
    const auto w = balanceOf<TypeParam>(
        "edge inflow",
        column( -5000.0, "impermeable", duration, inflowToml( "top", flux ) ) );
    EXPECT_LT(
        mpm_test::relativeDifference( w.flow_in, flux * width * duration ),
        3.0e-4 );
    EXPECT_LT( w.relativeClosureError(), 6.0e-6 );
}

} // namespace
