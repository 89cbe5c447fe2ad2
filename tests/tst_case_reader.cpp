// The case reader: valid cases in full, defaults, errors (the bad case
// files: tst_bad_cases.cpp).
#include <io/mpm_case_reader.hpp>
#include <mpm_test_case_reader.hpp>
#include <mpm_test_minimal_case.hpp>

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#ifndef RAINSLIDE_TEST_DATA_DIR
#define RAINSLIDE_TEST_DATA_DIR "/work/main/tests/data"
#endif

namespace
{
using mpm::Point2;

//! Expects the elastic parameters of `m`: density (kg/m^3), E (Pa), nu.
void expectElastic( const mpm::MaterialConfig& m, const double density,
                    const double youngs_modulus, const double poisson_ratio )
{
    EXPECT_DOUBLE_EQ( m.density_kg_per_m3, density );
    EXPECT_DOUBLE_EQ( m.youngs_modulus_pa, youngs_modulus );
    EXPECT_DOUBLE_EQ( m.poisson_ratio, poisson_ratio );
}

//! Expects the Mohr-Coulomb strength of `m`: peak and residual cohesion
//! (Pa), friction angle (degrees).
void expectStrength( const mpm::MaterialConfig& m, const double peak,
                     const double residual, const double friction_deg )
{
    EXPECT_DOUBLE_EQ( m.cohesion_peak_pa, peak );
    EXPECT_DOUBLE_EQ( m.cohesion_residual_pa, residual );
    EXPECT_DOUBLE_EQ( m.friction_angle_deg, friction_deg );
}

//! Expects the two-phase parameters of `m`: rho_s (kg/m^3), n, k (m^2).
void expectPoreSpace( const mpm::MaterialConfig& m, const double solid_density,
                      const double porosity, const double permeability )
{
    EXPECT_DOUBLE_EQ( m.solid_density_kg_per_m3, solid_density );
    EXPECT_DOUBLE_EQ( m.porosity, porosity );
    EXPECT_DOUBLE_EQ( m.permeability_m2, permeability );
}

//! Expects the retention law `r` to be `model` between the saturations
//! `residual` and `saturated`.
void expectSaturations( const mpm::RetentionConfig& r,
                        const mpm::RetentionType model, const double residual,
                        const double saturated )
{
    EXPECT_EQ( r.model, model );
    EXPECT_DOUBLE_EQ( r.residual_saturation, residual );
    EXPECT_DOUBLE_EQ( r.saturated_saturation, saturated );
}

//---------------------------------------------------------------------------//
// Case reader: a valid case.
//---------------------------------------------------------------------------//
TEST( CaseReader, reads_good_case )
{
    const std::string path = RAINSLIDE_TEST_DATA_DIR "/good_case.toml";
    const mpm::CaseConfig c = mpm::readCaseFile( path );
    EXPECT_EQ( c.file, path );
    EXPECT_EQ( c.name, "good_slope-1" );
    EXPECT_EQ( c.description,
               "Dry slope: gravity loading, then strength reduction" );
    EXPECT_EQ( c.grid.origin_m, ( Point2{ -1.0, 0.0 } ) );
    EXPECT_DOUBLE_EQ( c.grid.cell_size_m, 0.5 );
    EXPECT_EQ( c.grid.cells, ( std::array<int, 2>{ 42, 20 } ) );
    EXPECT_EQ( c.points_per_cell_per_direction, 3 );

    // Materials, in file order.
    ASSERT_EQ( c.materials.size(), 2u );
    const mpm::MaterialConfig& soil = c.materials[0];
    EXPECT_EQ( soil.name, "soil" );
    EXPECT_EQ( soil.model, mpm::ModelType::MohrCoulomb );
    expectElastic( soil, 1900.0, 1.0e7, 0.33 );
    expectStrength( soil, 20.0e3, 100.0, 20.0 );
    EXPECT_DOUBLE_EQ( soil.softening_modulus_pa, -250e3 );
    EXPECT_DOUBLE_EQ( soil.dilation_angle_deg, 0.1 );
    EXPECT_EQ( c.materials[1].model, mpm::ModelType::LinearElastic );
    EXPECT_DOUBLE_EQ( c.materials[1].density_kg_per_m3, 2500.0 );

    // Bodies: material ids; the repeated closing vertex is dropped.
    ASSERT_EQ( c.bodies.size(), 2u );
    EXPECT_EQ( c.bodies[0].material, "rock" );
    EXPECT_EQ( c.bodies[0].material_id, 1 );
    EXPECT_EQ( c.bodies[0].polygon_m.size(), 4u );
    EXPECT_EQ( c.bodies[1].material_id, 0 );
    EXPECT_EQ( c.bodies[1].polygon_m.size(), 6u );

    ASSERT_EQ( c.boundaries.size(), 3u );
    EXPECT_EQ( c.boundaries[0].where, mpm::BoundarySelector::Left );
    EXPECT_EQ( c.boundaries[0].condition, mpm::BoundaryCondition::FixX );
    EXPECT_EQ( c.boundaries[2].where, mpm::BoundarySelector::BelowPolyline );
    EXPECT_EQ( c.boundaries[2].condition, mpm::BoundaryCondition::Fixed );
    EXPECT_EQ( c.boundaries[2].polyline_m.size(), 3u );

    // Solver: given values and defaults.
    EXPECT_DOUBLE_EQ( c.solver.courant_number, 0.4 );
    EXPECT_DOUBLE_EQ( c.solver.flip_fraction, 1.0 );
    EXPECT_TRUE( c.solver.bbar );
    EXPECT_DOUBLE_EQ( c.solver.dt_s, 0.0 );
    EXPECT_FALSE( c.solver.remove_points_leaving_grid );
    EXPECT_DOUBLE_EQ( c.solver.instability_speed_factor, 10.0 );

    ASSERT_EQ( c.stages.size(), 2u );
    const mpm::StageConfig& gravity = c.stages[0];
    EXPECT_EQ( gravity.name, "gravity" );
    EXPECT_EQ( gravity.type, mpm::StageType::QuasiStatic );
    EXPECT_DOUBLE_EQ( gravity.damping, 0.7 );
    EXPECT_DOUBLE_EQ( gravity.duration_s, 5.0 );
    EXPECT_DOUBLE_EQ( gravity.ke_ratio_tolerance, 1e-5 );
    EXPECT_DOUBLE_EQ( gravity.snapshot_interval_s, 0.0 );
    EXPECT_TRUE( gravity.reset_displacement );
    EXPECT_EQ( gravity.gravity_m_per_s2, ( Point2{ 0.0, -9.81 } ) );
    // Override: soil is linear elastic in this stage; rock is unchanged.
    ASSERT_EQ( gravity.materials.size(), 2u );
    EXPECT_EQ( gravity.materials[0].model, mpm::ModelType::LinearElastic );
    EXPECT_DOUBLE_EQ( gravity.materials[0].youngs_modulus_pa, 1.0e7 );
    EXPECT_DOUBLE_EQ( gravity.materials[0].cohesion_peak_pa, 0.0 );
    EXPECT_EQ( gravity.materials[1].name, "rock" );
    EXPECT_EQ( gravity.boundaries.size(), 3u );

    const mpm::StageConfig& failure = c.stages[1];
    EXPECT_EQ( failure.type, mpm::StageType::Dynamic );
    EXPECT_DOUBLE_EQ( failure.damping, 0.0 );
    EXPECT_DOUBLE_EQ( failure.duration_s, 10.0 );
    EXPECT_DOUBLE_EQ( failure.snapshot_interval_s, 0.5 );
    EXPECT_FALSE( failure.reset_displacement );
    EXPECT_EQ( failure.materials[0].model, mpm::ModelType::MohrCoulomb );
    expectStrength( failure.materials[0], 15.0e3, 100.0, 20.0 );
    ASSERT_EQ( failure.boundaries.size(), 1u );
    EXPECT_EQ( failure.boundaries[0].where, mpm::BoundarySelector::Bottom );
}

//---------------------------------------------------------------------------//
// Case reader: a valid unsaturated two-phase case.
//---------------------------------------------------------------------------//
TEST( CaseReader, reads_good_two_phase_case )
{
    const std::string path =
        RAINSLIDE_TEST_DATA_DIR "/good_two_phase_case.toml";
    const mpm::CaseConfig c = mpm::readCaseFile( path );
    EXPECT_EQ( c.name, "rain_column" );
    EXPECT_EQ( c.analysis, mpm::AnalysisType::Unsaturated );

    // [water]: given values and the default viscosity.
    EXPECT_DOUBLE_EQ( c.water.density_kg_per_m3, 998.0 );
    EXPECT_DOUBLE_EQ( c.water.bulk_modulus_pa, 2.0e9 );
    EXPECT_DOUBLE_EQ( c.water.viscosity_pa_s, 1.0e-3 );

    // Materials: two-phase parameters; the bulk density is not given.
    ASSERT_EQ( c.materials.size(), 2u );
    const mpm::MaterialConfig& sand = c.materials[0];
    EXPECT_EQ( sand.name, "sand" );
    EXPECT_EQ( sand.model, mpm::ModelType::MohrCoulomb );
    EXPECT_DOUBLE_EQ( sand.density_kg_per_m3, 0.0 );
    expectPoreSpace( sand, 2700.0, 0.3, 4.5e-9 );
    EXPECT_DOUBLE_EQ( sand.youngs_modulus_pa, 1.0e7 );
    expectStrength( sand, 1.0e3, 1.0e3, 30.0 );
    const mpm::RetentionConfig& vg = sand.retention;
    expectSaturations( vg, mpm::RetentionType::VanGenuchten, 0.23, 1.0 );
    EXPECT_DOUBLE_EQ( vg.alpha_per_pa, 4.4e-4 );
    EXPECT_DOUBLE_EQ( vg.n, 3.04 );
    EXPECT_DOUBLE_EQ( vg.k_rel_min, 1.0e-4 );

    const mpm::MaterialConfig& clay = c.materials[1];
    EXPECT_EQ( clay.model, mpm::ModelType::LinearElastic );
    expectPoreSpace( clay, 2650.0, 0.45, 1.0e-14 );
    // Liakopoulos with every default (inline table).
    expectSaturations( clay.retention, mpm::RetentionType::Liakopoulos, 0.0,
                       1.0 );
    EXPECT_DOUBLE_EQ( clay.retention.k_rel_min, 0.0 );

    // Bodies: initial pore pressure p_w = a + b y, defaults 0.
    ASSERT_EQ( c.bodies.size(), 2u );
    EXPECT_EQ( c.bodies[0].material_id, 1 );
    EXPECT_DOUBLE_EQ( c.bodies[0].initial_pore_pressure_pa, 0.0 );
    EXPECT_DOUBLE_EQ( c.bodies[0].initial_pore_pressure_gradient_pa_per_m,
                      -9810.0 );
    EXPECT_EQ( c.bodies[1].material_id, 0 );
    EXPECT_DOUBLE_EQ( c.bodies[1].initial_pore_pressure_pa, -50.0e3 );
    EXPECT_DOUBLE_EQ( c.bodies[1].initial_pore_pressure_gradient_pa_per_m,
                      0.0 );

    // Boundaries: hydraulic conditions; a purely hydraulic boundary.
    ASSERT_EQ( c.boundaries.size(), 4u );
    for ( int k = 0; k < 2; ++k )
    {
        EXPECT_EQ( c.boundaries[k].condition, mpm::BoundaryCondition::FixX );
        EXPECT_EQ( c.boundaries[k].hydraulic,
                   mpm::HydraulicCondition::Impermeable );
        EXPECT_TRUE( c.boundaries[k].constrains_solid );
    }
    EXPECT_EQ( c.boundaries[2].where, mpm::BoundarySelector::Bottom );
    EXPECT_EQ( c.boundaries[2].condition, mpm::BoundaryCondition::Fixed );
    EXPECT_EQ( c.boundaries[2].hydraulic, mpm::HydraulicCondition::Drained );
    EXPECT_TRUE( c.boundaries[2].constrains_solid );
    EXPECT_EQ( c.boundaries[3].where, mpm::BoundarySelector::Top );
    EXPECT_EQ( c.boundaries[3].hydraulic,
               mpm::HydraulicCondition::Impermeable );
    EXPECT_FALSE( c.boundaries[3].constrains_solid );

    ASSERT_EQ( c.stages.size(), 2u );
    // Stage 1: permeability override of sand; a box load.
    const mpm::StageConfig& gravity = c.stages[0];
    EXPECT_DOUBLE_EQ( gravity.materials[0].permeability_m2, 1.0e-8 );
    EXPECT_DOUBLE_EQ( gravity.materials[0].porosity, 0.3 );
    EXPECT_EQ( gravity.materials[0].retention.model,
               mpm::RetentionType::VanGenuchten );
    EXPECT_DOUBLE_EQ( gravity.materials[0].retention.n, 3.04 );
    EXPECT_DOUBLE_EQ( gravity.materials[1].permeability_m2, 1.0e-14 );
    EXPECT_EQ( gravity.boundaries.size(), 4u );
    EXPECT_TRUE( gravity.pore_pressures.empty() );
    ASSERT_EQ( gravity.loads.size(), 1u );
    const mpm::PointLoad& load = gravity.loads[0];
    EXPECT_EQ( load.points.kind, mpm::PointSelection::Kind::Box );
    EXPECT_EQ( load.points.box_m[0], ( Point2{ 0.0, 0.99 } ) );
    EXPECT_EQ( load.points.box_m[1], ( Point2{ 0.05, 1.0 } ) );
    EXPECT_EQ( load.traction_pa, ( Point2{ 0.0, -10.0e3 } ) );
    EXPECT_DOUBLE_EQ( load.length_m, 0.05 );
    EXPECT_EQ( load.time_function,
               ( mpm::TimeFunction{ { 0.0, 0.0 }, { 0.005, 1.0 } } ) );

    // Stage 2: the clay's retention law replaced whole; prescribed pore
    // pressures; stage boundaries; a load without a time function.
    const mpm::StageConfig& rain = c.stages[1];
    EXPECT_DOUBLE_EQ( rain.materials[0].permeability_m2, 4.5e-9 );
    const mpm::RetentionConfig& linear = rain.materials[1].retention;
    EXPECT_EQ( linear.model, mpm::RetentionType::Linear );
    EXPECT_DOUBLE_EQ( linear.residual_saturation, 0.1 );
    EXPECT_DOUBLE_EQ( linear.saturated_saturation, 0.95 );
    EXPECT_DOUBLE_EQ( linear.suction_range_pa, 50.0e3 );
    EXPECT_DOUBLE_EQ( linear.k_rel_min, 0.0 );
    ASSERT_EQ( rain.pore_pressures.size(), 2u );
    const mpm::PorePressureCondition& surface = rain.pore_pressures[0];
    EXPECT_EQ( surface.points.kind, mpm::PointSelection::Kind::SurfaceCells );
    EXPECT_DOUBLE_EQ( surface.pressure_pa, 0.0 );
    EXPECT_EQ( surface.time_function,
               ( mpm::TimeFunction{ { 0.0, 0.0 }, { 0.01, 1.0 } } ) );
    const mpm::PorePressureCondition& box = rain.pore_pressures[1];
    EXPECT_EQ( box.points.kind, mpm::PointSelection::Kind::Box );
    EXPECT_EQ( box.points.box_m[0], ( Point2{ 0.0, 0.9 } ) );
    EXPECT_EQ( box.points.box_m[1], ( Point2{ 0.2, 1.0 } ) );
    EXPECT_DOUBLE_EQ( box.pressure_pa, -1.0e3 );
    EXPECT_TRUE( box.time_function.empty() );
    ASSERT_EQ( rain.boundaries.size(), 1u );
    EXPECT_EQ( rain.boundaries[0].hydraulic,
               mpm::HydraulicCondition::Impermeable );
    ASSERT_EQ( rain.loads.size(), 1u );
    EXPECT_EQ( rain.loads[0].points.kind,
               mpm::PointSelection::Kind::SurfaceCells );
    EXPECT_EQ( rain.loads[0].traction_pa, ( Point2{ 1.0e3, 0.0 } ) );
    EXPECT_DOUBLE_EQ( rain.loads[0].length_m, 0.2 );
    EXPECT_TRUE( rain.loads[0].time_function.empty() );
}

//---------------------------------------------------------------------------//
using mpm_test::minimal_case;
using namespace mpm_test::case_reader;

TEST( CaseReader, defaults_of_a_minimal_case )
{
    const mpm::CaseConfig c = mpm::parseCase( minimal_case, "minimal.toml" );
    EXPECT_EQ( c.file, "minimal.toml" );
    EXPECT_EQ( c.points_per_cell_per_direction, 2 );
    EXPECT_TRUE( c.boundaries.empty() );
    // Residual cohesion defaults to the peak; softening and dilation to 0.
    EXPECT_DOUBLE_EQ( c.materials[0].cohesion_residual_pa, 10.0e3 );
    EXPECT_DOUBLE_EQ( c.materials[0].softening_modulus_pa, 0.0 );
    EXPECT_DOUBLE_EQ( c.materials[0].dilation_angle_deg, 0.0 );
    EXPECT_DOUBLE_EQ( c.stages[0].damping, 0.7 );
    EXPECT_DOUBLE_EQ( c.stages[0].ke_ratio_tolerance, 1.0e-4 );
    EXPECT_EQ( c.stages[0].materials.size(), 1u );
    EXPECT_DOUBLE_EQ( c.solver.courant_number, 0.5 );
    EXPECT_DOUBLE_EQ( c.solver.flip_fraction, 0.99 );
}

TEST( CaseReader, reports_every_error_in_file_order )
{
    std::string text = minimal_case;
    text.replace( text.find( "duration_s = 2.0" ), 16, "duration_s = -1" );
    text.replace( text.find( "poisson_ratio = 0.3" ), 19,
                  "poisson_ratio = 0.5" );
    try
    {
        mpm::parseCase( text, "two.toml" );
        FAIL() << "expected a CaseError";
    }
    catch ( const mpm::CaseError& e )
    {
        const std::string msg = e.what();
        EXPECT_EQ( msg,
                   "two.toml:13:17: error: key 'materials[0].poisson_ratio': "
                   "expected a number in [0, 0.5), found 0.5\n"
                   "two.toml:22:14: error: key 'stages[0].duration_s': "
                   "expected a number > 0 s, found -1" );
    }
}

//---------------------------------------------------------------------------//
// Two-phase variants of the minimal case.
//---------------------------------------------------------------------------//
TEST( CaseReader, dry_case_leaves_two_phase_members_at_defaults )
{
    const mpm::CaseConfig c = mpm::parseCase( minimal_case, "minimal.toml" );
    EXPECT_EQ( c.analysis, mpm::AnalysisType::Dry );
    EXPECT_DOUBLE_EQ( c.water.density_kg_per_m3, 1000.0 );
    EXPECT_DOUBLE_EQ( c.water.bulk_modulus_pa, 2.2e9 );
    EXPECT_DOUBLE_EQ( c.materials[0].density_kg_per_m3, 2000.0 );
    EXPECT_DOUBLE_EQ( c.materials[0].porosity, 0.0 );
    EXPECT_EQ( c.materials[0].retention.model, mpm::RetentionType::Saturated );
    EXPECT_DOUBLE_EQ( c.bodies[0].initial_pore_pressure_pa, 0.0 );
    EXPECT_TRUE( c.stages[0].pore_pressures.empty() );
    EXPECT_TRUE( c.stages[0].loads.empty() );

    // analysis = "dry" written out is the same.
    std::string text = minimal_case;
    text.replace( text.find( "[grid]" ), 0, "analysis = \"dry\"\n" );
    EXPECT_EQ( mpm::parseCase( text, "dry.toml" ).analysis,
               mpm::AnalysisType::Dry );
}

TEST( CaseReader, saturated_case_has_no_retention_law )
{
    const mpm::CaseConfig c =
        mpm::parseCase( twoPhaseCase( "saturated" ), "saturated.toml" );
    EXPECT_EQ( c.analysis, mpm::AnalysisType::Saturated );
    const mpm::MaterialConfig& m = c.materials[0];
    EXPECT_DOUBLE_EQ( m.density_kg_per_m3, 0.0 );
    expectPoreSpace( m, 2650.0, 0.4, 1.0e-12 );
    EXPECT_EQ( m.retention.model, mpm::RetentionType::Saturated );
    EXPECT_EQ( c.stages[0].materials[0].retention.model,
               mpm::RetentionType::Saturated );
    // No [water] table: the defaults.
    EXPECT_DOUBLE_EQ( c.water.density_kg_per_m3, 1000.0 );
    EXPECT_DOUBLE_EQ( c.water.bulk_modulus_pa, 2.2e9 );
    EXPECT_DOUBLE_EQ( c.water.viscosity_pa_s, 1.0e-3 );
}

//! The retention law of the unsaturated two-phase case with `retention`,
//! read as `file`.
mpm::RetentionConfig retentionOf( const std::string& retention,
                                  const std::string& file )
{
    return mpm::parseCase( twoPhaseCase( "unsaturated", retention ), file )
        .materials[0]
        .retention;
}

TEST( CaseReader, reads_gardner_and_linear_retention )
{
    const mpm::RetentionConfig g = retentionOf(
        "retention = { model = \"gardner\", residual_saturation = 0.05, "
        "saturated_saturation = 0.98, alpha_per_m = 2.5, k_rel_min = 1e-6 }\n",
        "gardner.toml" );
    expectSaturations( g, mpm::RetentionType::Gardner, 0.05, 0.98 );
    EXPECT_DOUBLE_EQ( g.alpha_per_m, 2.5 );
    EXPECT_DOUBLE_EQ( g.k_rel_min, 1e-6 );

    const mpm::RetentionConfig l =
        retentionOf( "[materials.retention]\nmodel = \"linear\"\n"
                     "residual_saturation = 0\nsuction_range_pa = 2e4\n",
                     "linear.toml" );
    expectSaturations( l, mpm::RetentionType::Linear, 0.0, 1.0 );
    EXPECT_DOUBLE_EQ( l.suction_range_pa, 2e4 );
}

TEST( CaseReader, invalid_analysis_gives_no_follow_on_errors )
{
    // Two-phase keys in a case whose analysis is misspelt (value or key):
    // only the analysis is reported.
    std::string text = twoPhaseCase( "unsatruated" );
    text += "[[stages.pore_pressures]]\nwhere = \"surface_cells\"\n"
            "pressure_pa = 0.0\n";
    const std::string value_errors = errorsOf( text );
    EXPECT_EQ( value_errors.find( '\n' ), std::string::npos ) << value_errors;
    EXPECT_NE( value_errors.find( "did you mean \"unsaturated\"?" ),
               std::string::npos )
        << value_errors;

    text.replace( text.find( "analysis =" ), 8, "analyses" );
    const std::string key_errors = errorsOf( text );
    EXPECT_EQ( key_errors.find( '\n' ), std::string::npos ) << key_errors;
    EXPECT_NE( key_errors.find( "did you mean 'analysis'?" ),
               std::string::npos )
        << key_errors;
}

TEST( CaseReader, reports_every_two_phase_error )
{
    // Three mistakes in two tables, all reported in file order.
    std::string text = twoPhaseCase( "unsaturated" );
    text.replace( text.find( "porosity = 0.4" ), 14, "porosity = 1.0" );
    text += "[[stages.loads]]\nwhere = \"box\"\nbox_m = [[1.0, 1.0], "
            "[0.0, 2.0]]\ntraction_pa = [0.0, -1.0]\nlength_m = 1.0\n";
    EXPECT_EQ( errorsOf( text ),
               "x.toml:9:1: error: key 'materials[0].retention': required "
               "key is missing; expected a table [materials.retention] with "
               "the soil-water retention law (required for case.analysis = "
               "\"unsaturated\")\n"
               "x.toml:13:12: error: key 'materials[0].porosity': expected a "
               "number in (0, 1), found 1.0\n"
               "x.toml:28:22: error: key 'stages[0].loads[0].box_m[1]': "
               "expected the upper-right corner [x_max, y_max] with x_max >= "
               "1 m and y_max >= 1 m (the lower-left corner "
               "stages[0].loads[0].box_m[0]), found [0, 2] m" );
}

TEST( CaseReader, missing_file_is_reported )
{
    const std::string path = RAINSLIDE_TEST_DATA_DIR "/no_such_case.toml";
    try
    {
        mpm::readCaseFile( path );
        FAIL() << "expected a CaseError";
    }
    catch ( const mpm::CaseError& e )
    {
        EXPECT_NE(
            std::string( e.what() ).find( path + ": error: cannot open" ),
            std::string::npos )
            << e.what();
    }
}

} // namespace
