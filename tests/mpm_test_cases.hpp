#ifndef MPM_TEST_CASES_HPP
#define MPM_TEST_CASES_HPP

#include <case/mpm_case_config.hpp>

#include <string>

namespace mpm_test
{
//! Linear elastic material.
inline mpm::MaterialConfig elasticMaterial( const double E, const double nu,
                                            const double rho )
{
    mpm::MaterialConfig m;
    m.name = "soil";
    m.model = mpm::ModelType::LinearElastic;
    m.density_kg_per_m3 = rho;
    m.youngs_modulus_pa = E;
    m.poisson_ratio = nu;
    return m;
}

//! A grid from the origin of `nx` x `ny` cells of `cell_size_m`.
inline mpm::GridConfig gridConfig( const double cell_size_m, const int nx,
                                   const int ny )
{
    mpm::GridConfig grid;
    grid.origin_m = { 0.0, 0.0 };
    grid.cell_size_m = cell_size_m;
    grid.cells = { nx, ny };
    return grid;
}

//! The boundary condition `condition` on the grid edge `where`.
inline mpm::BoundaryConfig
boundaryConfig( const mpm::BoundarySelector where,
                const mpm::BoundaryCondition condition )
{
    mpm::BoundaryConfig boundary;
    boundary.where = where;
    boundary.condition = condition;
    return boundary;
}

//! A stage `name` of `type`, `duration_s` long, under the gravity
//! (0, `gravity_y`) m/s^2 with local `damping`.
inline mpm::StageConfig stageConfig( const std::string& name,
                                     const mpm::StageType type,
                                     const double duration_s,
                                     const double gravity_y,
                                     const double damping = 0.0 )
{
    mpm::StageConfig stage;
    stage.name = name;
    stage.type = type;
    stage.gravity_m_per_s2 = { 0.0, gravity_y };
    stage.damping = damping;
    stage.duration_s = duration_s;
    return stage;
}

/*!
  \brief A column one cell wide and `height` high on a fixed base with
  rollers on both sides (1D conditions), one stage.
*/
inline mpm::CaseConfig columnCase( const double height, const double h,
                                   const mpm::MaterialConfig& material,
                                   const mpm::StageConfig& stage )
{
    mpm::CaseConfig c;
    c.file = "<test>";
    c.name = "column";
    c.grid.origin_m = { 0.0, 0.0 };
    c.grid.cell_size_m = h;
    const int cells_high = static_cast<int>( height / h + 0.5 );
    c.grid.cells = { 1, cells_high + 2 };
    c.materials = { material };
    mpm::BodyConfig body;
    body.material = material.name;
    body.polygon_m = {
        { 0.0, 0.0 }, { h, 0.0 }, { h, height }, { 0.0, height } };
    c.bodies = { body };
    c.boundaries = { boundaryConfig( mpm::BoundarySelector::Left,
                                     mpm::BoundaryCondition::FixX ),
                     boundaryConfig( mpm::BoundarySelector::Right,
                                     mpm::BoundaryCondition::FixX ),
                     boundaryConfig( mpm::BoundarySelector::Bottom,
                                     mpm::BoundaryCondition::Fixed ) };
    mpm::StageConfig s = stage;
    s.materials = c.materials;
    s.boundaries = c.boundaries;
    c.stages = { s };
    return c;
}

//! A saturated two-phase linear elastic soil.
inline mpm::MaterialConfig saturatedMaterial( const double E, const double nu,
                                              const double rho_s,
                                              const double n, const double k )
{
    mpm::MaterialConfig m = elasticMaterial( E, nu, 0.0 );
    m.solid_density_kg_per_m3 = rho_s;
    m.porosity = n;
    m.permeability_m2 = k;
    return m;
}

//! Gives m the paper's van Genuchten retention (alpha = 0.44 / kPa,
//! n = 3.04, S_res = 0.23, S_sat = 1; verification.md 5.1).
inline mpm::MaterialConfig withPaperRetention( mpm::MaterialConfig m )
{
    m.retention.model = mpm::RetentionType::VanGenuchten;
    m.retention.residual_saturation = 0.23;
    m.retention.saturated_saturation = 1.0;
    m.retention.alpha_per_pa = 4.4e-4;
    m.retention.n = 3.04;
    return m;
}

//! The slope study's soil, linear elastic (Table 2): E = 1e7 Pa, nu = 0.33,
//! rho_s = 2700, n = 0.3, k = 4.5e-9 m^2 (K = 0.0441 m/s), with the paper's
//! retention.
inline mpm::MaterialConfig paperSoil()
{
    return withPaperRetention(
        saturatedMaterial( 1.0e7, 0.33, 2700.0, 0.3, 4.5e-9 ) );
}

//! An unsaturated column (columnCase, 0.25 m cells) of the paper's soil and
//! one dynamic stage "rain" of `duration_s` under the gravity (0,
//! `gravity_y`) m/s^2.
inline mpm::CaseConfig paperSoilColumn( const double height,
                                        const double duration_s,
                                        const double gravity_y )
{
    auto config = columnCase(
        height, 0.25, paperSoil(),
        stageConfig( "rain", mpm::StageType::Dynamic, duration_s, gravity_y ) );
    config.analysis = mpm::AnalysisType::Unsaturated;
    return config;
}

//! An inflow of `flux_m_per_s` on the points of the surface cells.
inline mpm::WaterInflow surfaceCellsInflow( const double flux_m_per_s )
{
    mpm::WaterInflow inflow;
    inflow.points.kind = mpm::PointSelection::Kind::SurfaceCells;
    inflow.flux_m_per_s = flux_m_per_s;
    return inflow;
}

/*!
  \brief Terzaghi consolidation column (verification.md 2.2): height H on a
  fixed impermeable base, rollers on the sides, drained top surface, no
  gravity, a traction sigma_c ramped on over t_ramp on the top points.
*/
inline mpm::CaseConfig terzaghiCase( const int cells, const double K_w,
                                     const double t_end, const double t_ramp )
{
    const double H = 1.0, h = H / cells;
    mpm::StageConfig stage = mpm_test::stageConfig(
        "consolidation", mpm::StageType::Dynamic, t_end, 0.0 );
    // E = 10 MPa, nu = 0, n = 0.3, rho_s = 2650, K = 1e-3 m/s.
    const double k = 1.0e-3 * 1.0e-3 / ( 1000.0 * 9.81 );
    auto c = columnCase( H, h, saturatedMaterial( 1.0e7, 0.0, 2650.0, 0.3, k ),
                         stage );
    c.analysis = mpm::AnalysisType::Saturated;
    c.water.bulk_modulus_pa = K_w;
    c.water.density_kg_per_m3 = 1000.0;
    c.water.viscosity_pa_s = 1.0e-3;
    mpm::PointLoad load;
    load.points.kind = mpm::PointSelection::Kind::Box;
    load.points.box_m = { mpm::Point2{ -1.0, H - 0.5 * h },
                          mpm::Point2{ 1.0, H } };
    load.traction_pa = { 0.0, -1.0e4 };
    load.length_m = h;
    load.time_function = { { 0.0, 0.0 }, { t_ramp, 1.0 } };
    c.stages[0].loads = { load };
    return c;
}

} // namespace mpm_test

#endif // MPM_TEST_CASES_HPP
