#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_water.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

namespace
{
MPM_TEST_BACKEND_SUITE( Inflow );

using mpm_test::waterVolume;

/*!
  Rainfall as a prescribed inflow flux: a sealed (all grid edges
  impermeable, grid top = soil top), weightless unsaturated column of the
  paper's van Genuchten soil at 20 kPa suction receives q = 1e-4 m/s on its
  0.25 m wide top for 2 s. The water it holds grows by q * width * t (the
  compressibility of water is negligible at these pressures) and the water
  spreads down (the lowest cell wets too).
*/
TYPED_TEST( Inflow, rainfall_flux_adds_its_water_volume )
{
    auto config = mpm_test::paperSoilColumn( 1.0, 2.0, 0.0 );
    config.grid.cells[1] = 4; // the top edge seals the soil's top
    config.bodies[0].initial_pore_pressure_pa = -2.0e4;
    mpm::WaterInflow inflow = mpm_test::surfaceCellsInflow( 1.0e-4 );
    inflow.length_m = 0.25;
    inflow.ponding = false;
    config.stages[0].inflows = { inflow };

    mpm::Simulation<TypeParam> sim( config );
    const double before = waterVolume( mpm::hostSnapshot( sim ) );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const auto snap = mpm::hostSnapshot( sim );
    const double added = waterVolume( snap ) - before;
    const double expected = 1.0e-4 * 0.25 * 2.0;
    EXPECT_NEAR( added, expected, 0.01 * expected );
    // The lowest cell received water too.
    double p_bottom = 0.0;
    int count = 0;
    for ( int p = 0; p < snap.num_points; ++p )
        if ( snap.x[2 * p + 1] < 0.25 )
        {
            p_bottom += snap.p_w[p];
            ++count;
        }
    EXPECT_GT( p_bottom / count, -2.0e4 + 100.0 );
}

} // namespace
