#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>
#include <mpm_test_water.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

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

//! What a rain did to the sealed column above in a stage of the seepage
//! scheme (long steps).
struct SeepageRain
{
    double taken_in; //!< the steps' rain, m^3 per m
    double stored;   //!< the change of the column's water, m^3 per m
    double longest;  //!< the longest step, s
};

/*!
  The sealed column above at 20 kPa of suction, weightless, under `inflow`
  (on its 0.25 m wide top, no ponding) for `duration` s of the seepage
  scheme, whose steps follow the flow's saturation change: hundreds of
  seconds under a light rain.
*/
template <class ExecSpace>
SeepageRain seepageRain( mpm::WaterInflow inflow, const double duration )
{
    auto config = mpm_test::paperSoilColumn( 1.0, duration, 0.0 );
    config.grid.cells[1] = 4;
    config.bodies[0].initial_pore_pressure_pa = -2.0e4;
    config.solver.scheme = mpm::TwoPhaseScheme::Seepage;
    inflow.length_m = 0.25;
    inflow.ponding = false;
    config.stages[0].inflows = { inflow };

    mpm::Simulation<ExecSpace> sim( config );
    const double before = waterVolume( mpm::hostSnapshot( sim ) );
    mpm::RunObserver observer;
    const mpm::RunSummary summary = mpm::runStages( sim, config, observer );
    const mpm::StageSummary& rain = summary.stages.back();
    const SeepageRain result{ rain.water.point_inflow,
                              waterVolume( mpm::hostSnapshot( sim ) ) - before,
                              rain.dt_max_s };
    std::printf( "%ld steps (longest %.1f s): taken in %.12e m3/m, stored "
                 "%.9e\n",
                 rain.steps, result.longest, result.taken_in, result.stored );
    return result;
}

// q = 1e-5 m/s x f(t), f rising from 0 to 1 over 1000 s: each step takes
// in q x width x the mean of f over its span, so the stage takes in
// q x width x 500 s exactly (a step that took the rate at its end would
// take in more); the column stores it.
TYPED_TEST( Inflow, a_ramped_rain_adds_its_integral_over_long_steps )
{
    mpm::WaterInflow inflow = mpm_test::surfaceCellsInflow( 1.0e-5 );
    inflow.time_function = { { { 0.0, 0.0 } }, { { 1000.0, 1.0 } } };
    const SeepageRain rain = seepageRain<TypeParam>( inflow, 1000.0 );
    const double expected = 1.0e-5 * 0.25 * 500.0;
    EXPECT_GT( rain.longest, 100.0 );
    EXPECT_NEAR( rain.taken_in / expected, 1.0, 1.0e-12 );
    EXPECT_NEAR( rain.stored / expected, 1.0, 1.0e-4 );
}

// A hyetograph (docs/case-file.md): nothing for 200 s, 36 mm/h for 400 s,
// 18 mm/h for 300 s, then dry: the steps that cross its jumps take in the
// blocks' depth over their spans, 0.25 m x (4 + 1.5) mm exactly.
TYPED_TEST( Inflow, a_hyetograph_adds_its_depth_over_long_steps )
{
    const auto config = mpm::parseCase(
        std::string(
            "[case]\nname = \"h\"\nanalysis = \"saturated\"\n"
            "[grid]\norigin_m = [0.0, 0.0]\ncell_size_m = 0.25\n"
            "cells = [1, 4]\n[particles]\npoints_per_cell = 2\n"
            "[[materials]]\nname = \"soil\"\nmodel = \"linear_elastic\"\n"
            "solid_density_kg_per_m3 = 2700.0\nporosity = 0.3\n"
            "permeability_m2 = 4.5e-9\nyoungs_modulus_pa = 1.0e7\n"
            "poisson_ratio = 0.33\n[[bodies]]\nmaterial = \"soil\"\n"
            "polygon_m = [[0.0, 0.0], [0.25, 0.0], [0.25, 1.0], [0.0, "
            "1.0]]\n[[stages]]\nname = \"s\"\ntype = \"dynamic\"\nduration_s = "
            "1.0\n"
            "[[stages.inflows]]\nwhere = \"surface_cells\"\n"
            "length_m = 1.0\nhyetograph_mm_per_h = [[200.0, 36.0], "
            "[600.0, 18.0], [900.0, 0.0]]\n" ),
        "h.toml" );
    const mpm::WaterInflow inflow = config.stages[0].inflows[0];
    const SeepageRain rain = seepageRain<TypeParam>( inflow, 1200.0 );
    const double expected = 0.25 * ( 4.0e-3 + 1.5e-3 );
    EXPECT_GT( rain.longest, 100.0 );
    EXPECT_NEAR( rain.taken_in / expected, 1.0, 1.0e-12 );
    EXPECT_NEAR( rain.stored / expected, 1.0, 1.0e-4 );
}

} // namespace
