#ifndef MPM_FIXED_STRESS_HPP
#define MPM_FIXED_STRESS_HPP

#include <mpm_particle_views.hpp>
#include <mpm_status_flags.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_point_water.hpp>

#include <Kokkos_Core.hpp>

//---------------------------------------------------------------------------//
// The quasi-static scheme's own kernels (QuasiStaticStep,
// docs/formulation.md §11): the fixed-stress split's skeleton storage, the
// points' stored water, and the water in transit between the flow and the
// skeleton's relaxation.
//---------------------------------------------------------------------------//

namespace mpm
{
namespace physics
{
//! The fixed-stress split's skeleton storage b = S^2 / E_c (1/Pa): the
//! pore volume a unit volume gains per pascal of p_w at a fixed total
//! stress, Bishop's S on both the effective stress and the pore volume,
//! E_c the constrained modulus (exact for one-dimensional compression).
KOKKOS_INLINE_FUNCTION double skeletonStorage( const double S,
                                               const double constrained )
{
    return S * S / constrained;
}
} // namespace physics

//---------------------------------------------------------------------------//
//! storage_p = physics::skeletonStorage of each active point with a free
//! p_w at its constrained modulus (K and G times modulusFactor), else 0.
template <class ExecSpace, class ScalarView>
void skeletonStorages( const ExecSpace& exec,
                       const ParticleViews<ExecSpace>& pv,
                       const WaterParticleViews<ExecSpace>& wv,
                       const physics::MaterialTable& materials,
                       const ScalarView& storage_p )
{
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto storage = unmanaged( storage_p );
    Kokkos::parallel_for(
        "mpm::skeleton_storages",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( points.status_p( p ) != point_active ||
                 water_points.p_w_condition_p( p ) >= 0 )
            {
                storage( p ) = 0.0;
                return;
            }
            const physics::MaterialParams& m =
                materials[points.material_p( p )];
            storage( p ) = physics::skeletonStorage(
                water_points.S_p( p ),
                m.constrainedModulus() *
                    m.modulusFactor( points.vol_p( p ), points.vol0_p( p ) ) );
        } );
}

//---------------------------------------------------------------------------//
//! stored_p = each point's stored water (physics::pointWaterVolume),
//! m^3 per metre.
template <class ExecSpace, class ScalarView>
void pointWaterVolumes( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const physics::WaterParams& water,
                        const ScalarView& stored_p )
{
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto stored = unmanaged( stored_p );
    const double K_w = water.bulk_modulus;
    Kokkos::parallel_for(
        "mpm::point_water_volumes",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            stored( p ) = physics::pointWaterVolume(
                points.vol_p( p ), water_points.n_p( p ), water_points.S_p( p ),
                water_points.p_w_p( p ), K_w );
        } );
}

//! The water a relaxation left (pointWaterInTransit), m^3 per metre.
struct RelaxationWater
{
    double in_transit = 0.0; //!< over the points with a free p_w
    double prescribed = 0.0; //!< given to hold prescribed p_w
};

//---------------------------------------------------------------------------//
/*!
  \brief The water in transit after a relaxation, transit_p = anticipated_p
  + stored_p - the water the point stores now (m^3 per metre), for the
  active points whose p_w is free: what the flow gave it for its skeleton's
  change (anticipated_p) less what the relaxation's change of its pore
  volume at its held p_w took up (the stored water then, stored_p, to now).
  A point with a prescribed p_w has none (0): the condition gave the water
  its pore volume took, summed as `prescribed`.
*/
template <class ExecSpace, class ScalarView>
RelaxationWater
pointWaterInTransit( const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
                     const WaterParticleViews<ExecSpace>& wv,
                     const physics::WaterParams& water,
                     const ScalarView& anticipated_p,
                     const ScalarView& stored_p, const ScalarView& transit_p )
{
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto anticipated = unmanaged( anticipated_p );
    const auto stored = unmanaged( stored_p );
    const auto transit = unmanaged( transit_p );
    const double K_w = water.bulk_modulus;
    RelaxationWater total;
    Kokkos::parallel_reduce(
        "mpm::water_in_transit",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& in_transit, double& prescribed ) {
            transit( p ) = 0.0;
            if ( points.status_p( p ) != point_active )
                return;
            const double taken_up =
                physics::pointWaterVolume(
                    points.vol_p( p ), water_points.n_p( p ),
                    water_points.S_p( p ), water_points.p_w_p( p ), K_w ) -
                stored( p );
            if ( water_points.p_w_condition_p( p ) >= 0 )
            {
                prescribed += taken_up;
                return;
            }
            transit( p ) = anticipated( p ) - taken_up;
            in_transit += transit( p );
        },
        Kokkos::Sum<double>( total.in_transit ),
        Kokkos::Sum<double>( total.prescribed ) );
    return total;
}

} // namespace mpm

#endif // MPM_FIXED_STRESS_HPP
