// The water a wetting column takes up does not depend on the time step
// (the PIC part of the FLIP/PIC blend scales with the step:
// Simulation::stepFlipFraction).
#include <mpm_test_backends.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <string>

namespace
{
MPM_TEST_BACKEND_SUITE( InfiltrationStep );

/*!
  A 5 m column of the slope study's soil (K = 0.044 m/s, van Genuchten) at
  50 kPa suction on 0.5 m cells, p_w = 0 held on its top cell's points (the
  paper's rainfall) for 2 s: by then the front is about 1 m deep. `solver`
  is the [solver] table.
*/
std::string wettingColumn( const std::string& solver )
{
    using namespace mpm_test;
    return "\n" + caseToml( "wetting_column", "unsaturated" ) +
           gridToml( "0.5", "[1, 12]" ) + slopeSoilToml() + "\n" +
           soilBodyToml( rectangleToml( "0.5", "5.0" ) ) +
           "initial_pore_pressure_pa = -50.0e3\n" +
           boundaryToml( "bottom", "fixed" ) + "[solver]\n" + solver + "\n" +
           stageToml( "rain", "dynamic", "2.0" ) +
           heldBoxToml( "[[0.0, 4.5], [0.5, 5.0]]", "0.0" );
}

//! Water taken up in 2 s, m^3 per metre.
template <class ExecSpace>
double infiltration( const std::string& solver )
{
    const auto config = mpm::parseCase( wettingColumn( solver ), "column" );
    mpm::Simulation<ExecSpace> sim( config );
    const double before = mpm_test::waterVolume( mpm::hostSnapshot( sim ) );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    return mpm_test::waterVolume( mpm::hostSnapshot( sim ) ) - before;
}

// The automatic step (Courant 0.9, about 2.6e-4 s) and a quarter of it take
// up the same water within 1 %. With a fixed FLIP fraction of 0.99 at every
// step the smaller step took up 5 % less.
TYPED_TEST( InfiltrationStep, water_taken_up_does_not_depend_on_the_step )
{
    const double automatic =
        infiltration<TypeParam>( "courant_number = 0.9\n" );
    const double quarter = infiltration<TypeParam>( "dt_s = 6.5e-5\n" );
    EXPECT_GT( automatic, 0.05 ); // about 0.1 m^3/m: the front moved
    EXPECT_NEAR( quarter, automatic, 0.01 * automatic );
}

} // namespace
