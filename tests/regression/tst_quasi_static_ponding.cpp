// Ponded infiltration into the long slope's dry soil (K = 4.4 cm/s): the
// quasi-static scheme takes in the water the seepage scheme takes in; the
// flow's steps start short at the start of the rain, when it takes in water
// fastest.
#include <mpm_test_backends.hpp>
#include <mpm_test_toml.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
template <class ExecSpace>
class QuasiStaticPonding : public ::testing::Test
{
};
TYPED_TEST_SUITE( QuasiStaticPonding, mpm_test::Backends,
                  mpm_test::BackendName );

/*!
  A column of the slope's soil (cases/slope_base.toml: Table 2, 0.5 m cells,
  two points a side), 5 m high on a fixed base, at 50 kPa of suction after
  a gravity stage; then `seconds` of rain as the slope's, p_w = 0 in the
  surface cells (the most the soil takes in), snapshots every `snapshot_s`.
  `solver` is the [solver] table.
*/
std::string pondedColumn( const std::string& solver, const double seconds,
                          const double snapshot_s )
{
    return R"([case]
name = "ponded_column"
analysis = "unsaturated"
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.5
cells = [1, 12]
[particles]
points_per_cell = 2
[[materials]]
name = "soil"
model = "mohr_coulomb"
solid_density_kg_per_m3 = 2700.0
porosity = 0.3
permeability_m2 = 4.5e-9
youngs_modulus_pa = 1.0e7
poisson_ratio = 0.33
cohesion_peak_pa = 20.0e3
friction_angle_deg = 20.0
dilation_angle_deg = 0.1
)" + mpm_test::paperRetentionToml() +
           mpm_test::soilBodyToml(
               "[[0.0, 0.0], [0.5, 0.0], [0.5, 5.0], [0.0, 5.0]]" ) +
           "initial_pore_pressure_pa = -50.0e3\n" + mpm_test::rollersToml() +
           mpm_test::boundaryToml( "bottom", "fixed" ) + R"([solver]
)" + solver +
           R"(
[[stages]]
name = "gravity_and_suction"
type = "quasi_static"
gravity_m_per_s2 = [0.0, -9.81]
damping = 0.7
duration_s = 20.0
reset_displacement = true
[[stages.pore_pressures]]
where = "box"
box_m = [[0.0, 0.0], [0.5, 6.0]]
pressure_pa = -50.0e3
[[stages]]
name = "rainfall"
type = "dynamic"
gravity_m_per_s2 = [0.0, -9.81]
snapshot_interval_s = )" +
           std::to_string( snapshot_s ) +
           "\nduration_s = " + std::to_string( seconds ) +
           R"(
[[stages.pore_pressures]]
where = "surface_cells"
pressure_pa = 0.0
)";
}

//! What the column's rain stage did.
struct PondedRain
{
    double taken_in; //!< water taken in, m^3 per m
    long retaken;    //!< steps given back and taken again
};

//! The water the column took in over the rain, m^3 per m, snapshots every
//! `snapshot_s` (the steps land on them).
template <class ExecSpace>
PondedRain pondedRain( const std::string& solver, const double seconds,
                       const double snapshot_s = 0.5 )
{
    const auto config = mpm::parseCase(
        pondedColumn( solver, seconds, snapshot_s ), "ponded_column" );
    mpm::Simulation<ExecSpace> sim( config );
    mpm::RunObserver quiet;
    const mpm::RunSummary summary = mpm::runStages( sim, config, quiet );
    const mpm::StageSummary& rain = summary.stages.back();
    std::string settings = solver;
    std::replace( settings.begin(), settings.end(), '\n', ' ' );
    std::printf( "Ponded column, %s%.0f s of rain: %ld steps (%ld retaken), "
                 "%.5f m3/m taken in (%.5f stored)\n",
                 settings.c_str(), seconds, rain.steps, sim.stepsRetaken(),
                 rain.water.flow_in,
                 rain.water.stored_end - rain.water.stored_start );
    return { rain.water.flow_in, sim.stepsRetaken() };
}

template <class ExecSpace>
double waterTakenIn( const std::string& solver, const double seconds )
{
    return pondedRain<ExecSpace>( solver, seconds ).taken_in;
}

// 5 s of rain: the seepage scheme takes in 0.1806 m3/m, the quasi-static
// scheme 1.4 % more at the default step and 1.7 % more at a fifth of it
// (its skeleton swells as the suction goes: more pore space to fill). Its
// water seeps on from step to step through the relaxations; a flow started
// from rest each step would take in less the smaller the steps.
TYPED_TEST( QuasiStaticPonding, takes_in_the_seepage_schemes_water )
{
    const double seepage =
        waterTakenIn<TypeParam>( "scheme = \"seepage\"\n", 5.0 );
    const double quasi_static =
        waterTakenIn<TypeParam>( "scheme = \"quasi_static\"\n", 5.0 );
    const double fine = waterTakenIn<TypeParam>(
        "scheme = \"quasi_static\"\nseepage_saturation_change = 0.002\n", 5.0 );
    EXPECT_NEAR( quasi_static / seepage, 1.0, 0.05 );
    EXPECT_NEAR( fine / seepage, 1.0, 0.05 );
}

// 10 s of rain, snapshots every second. The rain stage's first step is
// solver.seepage_initial_dt_s (0.01 s), whatever step the gravity stage
// reached; both schemes take in what the seepage scheme takes in at a tenth
// of the first step and of the saturation change (seepage 0.3 % less,
// quasi-static 0.5 % more: its skeleton swells). A first step of 1 s takes
// in 8 % too little (the pond's inflow is fastest at its start), and a step
// that changed a saturation by more than twice the target is given back and
// taken again, shorter.
TYPED_TEST( QuasiStaticPonding, a_stage_starts_with_short_steps )
{
    const double converged =
        pondedRain<TypeParam>( "scheme = \"seepage\"\nseepage_initial_dt_s = "
                               "0.001\nseepage_saturation_change = 0.001\n",
                               10.0, 1.0 )
            .taken_in;
    for ( const char* scheme : { "seepage", "quasi_static" } )
    {
        const PondedRain rain = pondedRain<TypeParam>(
            "scheme = \"" + std::string( scheme ) + "\"\n", 10.0, 1.0 );
        EXPECT_NEAR( rain.taken_in / converged, 1.0, 0.02 ) << scheme;
    }
    const PondedRain long_first = pondedRain<TypeParam>(
        "scheme = \"seepage\"\nseepage_initial_dt_s = 1.0\n", 10.0, 1.0 );
    EXPECT_LT( long_first.taken_in / converged, 0.97 );
    EXPECT_GT( long_first.retaken, 0 );
}

} // namespace
