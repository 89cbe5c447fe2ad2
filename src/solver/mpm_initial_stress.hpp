#ifndef MPM_INITIAL_STRESS_HPP
#define MPM_INITIAL_STRESS_HPP

#include <mpm_particle_views.hpp>
#include <mpm_status_flags.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_retention.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace mpm
{
//! Where the points were generated: n x n per cell of size h (m) of a grid
//! with origin (x0, y0) (m).
struct PointLattice
{
    double x0 = 0.0;
    double y0 = 0.0;
    double h = 1.0;
    int points_per_cell = 2;

    double spacing() const { return h / points_per_cell; }
};

//---------------------------------------------------------------------------//
/*!
  \brief Geostatic (K0) stress of a stage start (StageConfig::
  initial_stress_k0), on the host, tension positive:
    sigma_v = -g (weight per unit width of the column above the point),
    sigma'_yy = sigma_v + S p_w, sigma'_xx = sigma'_zz = K0 sigma_v + S p_w,
    sigma'_xy = 0.
  Columns are point-spacing-wide strips (w = h / n); in each cell row of a
  column the points' mass is spread evenly over the height they fill from
  the row's bottom (n_row w), so sigma_v is linear in y between the points
  whatever their place in the cell (Gauss or even layout) and exact under a
  level surface. K0 acts on the stress of the weight; the suction's share
  S p_w is isotropic (Bishop, chi = S, Eq. 11), so the total stress
  sigma' - S p_w vanishes at the surface. Dry: sigma = (K0 sigma_v,
  sigma_v). The mass is the mixture's: solid m_p plus pore water n S rho_w
  V. Under a slope the field is not in equilibrium (a damped stage settles
  it). Strain and eps_p_bar are left unchanged.
*/
template <class ExecSpace>
void setGeostaticStress( const double k0, const double gravity,
                         const PointLattice& lattice,
                         const physics::MaterialTable& materials,
                         const physics::WaterParams& water,
                         const bool unsaturated, ParticleViews<ExecSpace>& pv,
                         const WaterParticleViews<ExecSpace>& wv )
{
    const auto host = []( const auto& view ) {
        return Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), view );
    };
    const auto x = host( pv.x_p );
    const auto m = host( pv.m_p );
    const auto status = host( pv.status_p );
    const auto material = host( pv.material_p );
    auto sigma = host( pv.sigma_p );
    const auto vol = host( pv.vol_p );
    const bool two_phase = wv.p_w_p.extent( 0 ) > 0; // empty when dry
    const auto p_w = host( wv.p_w_p );
    const auto n = host( wv.n_p );
    const double w = lattice.spacing();

    // Weight per unit width (Pa) and Bishop's suction share S p_w of each
    // active point, by column and cell row (rows from the top down).
    const int num_points = pv.size();
    std::vector<double> weight( num_points, 0.0 ), s_p_w( num_points, 0.0 );
    std::map<long, std::map<long, std::vector<int>, std::greater<long>>>
        columns;
    for ( int p = 0; p < num_points; ++p )
    {
        if ( status( p ) != point_active )
            continue;
        double mass = m( p );
        if ( two_phase )
        {
            const double S =
                unsaturated ? physics::Retention{}(
                                  materials[material( p )].retention, p_w( p ) )
                                  .S
                            : 1.0;
            mass += n( p ) * S * water.density * vol( p );
            s_p_w[p] = S * p_w( p );
        }
        weight[p] = gravity * mass / w;
        const long column =
            static_cast<long>( std::floor( ( x( p, 0 ) - lattice.x0 ) / w ) );
        const long row = static_cast<long>(
            std::floor( ( x( p, 1 ) - lattice.y0 ) / lattice.h ) );
        columns[column][row].push_back( p );
    }

    for ( const auto& column : columns )
    {
        double above = 0.0; // weight per unit width of the rows above, Pa
        for ( const auto& row : column.second )
        {
            double row_weight = 0.0;
            for ( const int p : row.second )
                row_weight += weight[p];
            const double filled = std::min(
                lattice.h, static_cast<double>( row.second.size() ) * w );
            const double top = lattice.y0 + row.first * lattice.h + filled;
            for ( const int p : row.second )
            {
                const double sigma_v =
                    -( above + row_weight / filled * ( top - x( p, 1 ) ) );
                sigma( p, 0 ) = k0 * sigma_v + s_p_w[p];
                sigma( p, 1 ) = sigma_v + s_p_w[p];
                sigma( p, 2 ) = 0.0;
                sigma( p, 3 ) = k0 * sigma_v + s_p_w[p];
            }
            above += row_weight;
        }
    }
    Kokkos::deep_copy( pv.sigma_p, sigma );
}

} // namespace mpm

#endif // MPM_INITIAL_STRESS_HPP
