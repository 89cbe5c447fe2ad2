#include <setup/mpm_materials.hpp>

#include <cmath>
#include <stdexcept>

namespace mpm
{
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
        params.setAngles( m.friction_angle_deg * deg,
                          m.dilation_angle_deg * deg );
        table.materials[table.size++] = params;
    }
    return table;
}

} // namespace mpm
