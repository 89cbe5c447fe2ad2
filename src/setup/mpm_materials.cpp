#include <setup/mpm_materials.hpp>

#include <cmath>
#include <stdexcept>

namespace mpm
{
physics::RetentionParams retentionParams( const RetentionConfig& config,
                                          const double water_unit_weight )
{
    physics::RetentionParams r;
    // The model of each RetentionType, in the order of its values.
    static const physics::RetentionModel models[] = {
        physics::RetentionModel::Saturated,
        physics::RetentionModel::VanGenuchten,
        physics::RetentionModel::Liakopoulos, physics::RetentionModel::Gardner,
        physics::RetentionModel::Linear };
    r.model = models[static_cast<int>( config.model )];
    r.s_res = config.residual_saturation;
    r.s_sat = config.saturated_saturation;
    r.alpha_per_pa = config.alpha_per_pa;
    r.n_vg = config.n;
    r.alpha_per_m = config.alpha_per_m;
    r.rho_w_g = water_unit_weight;
    r.suction_range_pa = config.suction_range_pa;
    r.k_rel_min = config.k_rel_min;
    return r;
}

physics::MaterialTable
makeMaterialTable( const std::vector<MaterialConfig>& materials )
{
    physics::MaterialTable table;
    if ( static_cast<int>( materials.size() ) >
         physics::MaterialTable::capacity )
        throw std::invalid_argument(
            "at most " + std::to_string( physics::MaterialTable::capacity ) +
            " materials are supported, found " +
            std::to_string( materials.size() ) );
    const double deg = M_PI / 180.0;
    for ( const MaterialConfig& m : materials )
    {
        physics::MaterialParams params = physics::elasticParams(
            m.youngs_modulus_pa, m.poisson_ratio, m.density_kg_per_m3 );
        params.model = m.model == ModelType::MohrCoulomb
                           ? physics::Model::MohrCoulomb
                           : physics::Model::LinearElastic;
        params.cohesion_peak = m.cohesion_peak_pa;
        params.cohesion_residual = m.cohesion_residual_pa;
        params.softening_modulus = m.softening_modulus_pa;
        params.softening_measure =
            m.softening_measure == SofteningMeasureType::EngineeringShearStrain
                ? physics::SofteningMeasure::EngineeringShearStrain
                : physics::SofteningMeasure::EquivalentPlasticStrain;
        params.setAngles( m.friction_angle_deg * deg,
                          m.dilation_angle_deg * deg );
        params.setTensileStrength( m.tensile_strength_pa );
        params.permeability = m.permeability_m2;
        params.retention = retentionParams( m.retention );
        table.materials[table.size++] = params;
    }
    return table;
}

} // namespace mpm
