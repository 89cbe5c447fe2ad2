#ifndef MPM_WATER_CONTENT_HPP
#define MPM_WATER_CONTENT_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_point_water.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Water held by the points, m^3 per metre out of plane.
struct WaterContent
{
    double active = 0.0;  //!< in the simulated points
    double removed = 0.0; //!< carried off the grid by removed points
};

//! Stored water of the points (physics::pointWaterVolume), the active ones
//! and those removed after leaving the grid (their last state).
template <class ExecSpace>
WaterContent waterContent( const ExecSpace& exec_space,
                           const ParticleViews<ExecSpace>& pv,
                           const WaterParticleViews<ExecSpace>& wv,
                           const physics::WaterParams& water )
{
    WaterContent content;
    if ( !wv.allocated() )
        return content;
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const double bulk_modulus = water.bulk_modulus;
    Kokkos::parallel_reduce(
        "mpm::water_content",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& active, double& removed ) {
            const double stored = physics::pointWaterVolume(
                points.vol_p( p ), water_points.n_p( p ), water_points.S_p( p ),
                water_points.p_w_p( p ), bulk_modulus );
            if ( points.status_p( p ) == point_active )
                active += stored;
            else
                removed += stored;
        },
        Kokkos::Sum<double>( content.active ),
        Kokkos::Sum<double>( content.removed ) );
    return content;
}

} // namespace mpm

#endif // MPM_WATER_CONTENT_HPP
