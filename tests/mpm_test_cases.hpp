#ifndef MPM_TEST_CASES_HPP
#define MPM_TEST_CASES_HPP

#include <io/mpm_case_config.hpp>

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
    mpm::BoundaryConfig left, right, bottom;
    left.where = mpm::BoundarySelector::Left;
    left.condition = mpm::BoundaryCondition::FixX;
    right.where = mpm::BoundarySelector::Right;
    right.condition = mpm::BoundaryCondition::FixX;
    bottom.where = mpm::BoundarySelector::Bottom;
    bottom.condition = mpm::BoundaryCondition::Fixed;
    c.boundaries = { left, right, bottom };
    mpm::StageConfig s = stage;
    s.materials = c.materials;
    s.boundaries = c.boundaries;
    c.stages = { s };
    return c;
}

} // namespace mpm_test

#endif // MPM_TEST_CASES_HPP
