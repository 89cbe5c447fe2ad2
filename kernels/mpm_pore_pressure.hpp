#ifndef MPM_PORE_PRESSURE_HPP
#define MPM_PORE_PRESSURE_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_kinematics.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_retention.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Retention state of one material at a pressure (adapter for Newton).
struct RetentionAt
{
    physics::RetentionParams params;
    KOKKOS_INLINE_FUNCTION physics::RetentionState
    operator()( const double p_w ) const
    {
        return physics::Retention{}( params, p_w );
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Pore pressure, porosity and retention state of every point
  (formulation.md steps 6, 7, 9): p_w from the mass-conservative Eq. 8
  (explicit when saturated), prescribed point pressures, porosity from
  Eq. 2 as n' = 1 - (1 - n) / det(I + L dt), then S, dS/dp_w, k_rel.
  `prescribed_p_w(c)` is the current pressure of condition c, Pa;
  `inflow_rate(f)` the water volume inflow f adds per unit point volume
  and time (1/s), a source in Eq. 8; `inflow_ponding(f)` caps p_w at 0 on
  its points (the excess runs off).
*/
template <class ExecSpace, class PressureView, class RateView, class FlagView>
void porePressureUpdate(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double dt, const bool saturated, const PressureView& prescribed_p_w,
    const RateView& inflow_rate, const FlagView& inflow_ponding )
{
    const physics::Kinematics kinematics{ dt };
    const auto grad_v_p = pv.grad_v_p;
    const auto material_p = pv.material_p;
    const auto status_p = pv.status_p;
    const auto p_w_p = wv.p_w_p;
    const auto S_p = wv.S_p;
    const auto dS_dp_p = wv.dS_dp_p;
    const auto k_rel_p = wv.k_rel_p;
    const auto n_p = wv.n_p;
    const auto div_v_w_p = wv.div_v_w_p;
    const auto condition_p = wv.p_w_condition_p;
    const auto inflow_p = wv.inflow_p;

    Kokkos::parallel_for(
        "mpm::pore_pressure_update",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            const double L[2][2] = {
                { grad_v_p( p, 0, 0 ), grad_v_p( p, 0, 1 ) },
                { grad_v_p( p, 1, 0 ), grad_v_p( p, 1, 1 ) } };
            const double n = n_p( p );
            const double S = S_p( p );
            const double div_s = L[0][0] + L[1][1];
            // Water volume change per unit volume over the step (Eq. 8).
            const int inflow = inflow_p( p );
            const double source = inflow >= 0 ? inflow_rate( inflow ) : 0.0;
            const double volume_change =
                dt *
                ( source - n * S * div_v_w_p( p ) - ( 1.0 - n ) * S * div_s );
            const RetentionAt retention{ materials[material_p( p )].retention };
            double p_w = p_w_p( p );
            if ( saturated )
                p_w += volume_change * water.bulk_modulus / n;
            else
                p_w += physics::porePressureIncrement(
                    retention, p_w, S, n, water.bulk_modulus, volume_change );
            if ( inflow >= 0 && inflow_ponding( inflow ) && p_w > 0.0 )
                p_w = 0.0;
            if ( condition_p( p ) >= 0 )
                p_w = prescribed_p_w( condition_p( p ) );
            p_w_p( p ) = p_w;
            // Eq. 2 integrated over the step: (1 - n) V is constant.
            n_p( p ) = 1.0 - ( 1.0 - n ) / kinematics.volumeRatio( L );
            if ( !saturated )
            {
                const physics::RetentionState state = retention( p_w );
                S_p( p ) = state.S;
                dS_dp_p( p ) = state.dS_dp;
                k_rel_p( p ) = state.k_rel;
            }
        } );
}

} // namespace mpm

#endif // MPM_PORE_PRESSURE_HPP
