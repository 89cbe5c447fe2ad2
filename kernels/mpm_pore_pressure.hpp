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
//! Retention law of one material at a pressure (adapter for Newton).
struct RetentionAt
{
    physics::RetentionParams params;

    //! S and dS/dp_w at p_w (the Newton iterations).
    KOKKOS_INLINE_FUNCTION physics::SaturationState
    operator()( const double p_w ) const
    {
        return physics::Retention{}.saturationState( params, p_w );
    }

    //! S, dS/dp_w and k_rel at p_w.
    KOKKOS_INLINE_FUNCTION physics::RetentionState
    state( const double p_w ) const
    {
        return physics::Retention{}( params, p_w );
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Pore pressure, porosity and retention state of one point
  (formulation.md steps 6, 7, 9) from its velocity gradient L and water
  divergence div v_w: p_w from the mass-conservative Eq. 8 (explicit when
  saturated), prescribed point pressures, porosity from Eq. 2 as
  n' = 1 - (1 - n) / det(I + L dt), then S, dS/dp_w, k_rel.
  `prescribed_p_w(c)` is the current pressure of condition c, Pa;
  `inflow_rate(f)` the water volume inflow f adds per unit point volume
  and time (1/s), a source in Eq. 8; `inflow_ponding(f)` caps p_w at 0 on
  its points (the excess runs off). With `retention_current`, the stored
  S_p and dS_dp_p are the retention law's values at p_w_p (true after an
  unsaturated update with the same materials), which saves one retention
  evaluation per point.
*/
template <class ExecSpace, class PressureView, class RateView, class FlagView>
struct PorePressurePointUpdate
{
    using wv_type = WaterParticleViews<ExecSpace>;
    physics::Kinematics kinematics;
    physics::WaterParams water;
    bool saturated;
    bool retention_current;
    typename wv_type::scalar_view p_w_p, S_p, dS_dp_p, k_rel_p, n_p;
    typename wv_type::int_view condition_p, inflow_p;
    PressureView prescribed_p_w;
    RateView inflow_rate;
    FlagView inflow_ponding;

    KOKKOS_INLINE_FUNCTION void
    operator()( const int p, const double L[2][2], const double div_v_w,
                const physics::MaterialParams& params ) const
    {
        const double dt = kinematics.dt;
        const double n = n_p( p );
        const double S = S_p( p );
        const double div_s = L[0][0] + L[1][1];
        // Water volume change per unit volume over the step (Eq. 8).
        const int inflow = inflow_p( p );
        const double source = inflow >= 0 ? inflow_rate( inflow ) : 0.0;
        const double volume_change =
            dt * ( source - n * S * div_v_w - ( 1.0 - n ) * S * div_s );
        const RetentionAt retention{ params.retention };
        double p_w = p_w_p( p );
        if ( saturated )
            p_w += volume_change * water.bulk_modulus / n;
        else
        {
            const physics::SaturationState stored{ S, dS_dp_p( p ) };
            p_w += physics::porePressureIncrement(
                retention, p_w, S, n, water.bulk_modulus, volume_change,
                retention_current ? &stored : nullptr );
        }
        if ( inflow >= 0 && inflow_ponding( inflow ) && p_w > 0.0 )
            p_w = 0.0;
        if ( condition_p( p ) >= 0 )
            p_w = prescribed_p_w( condition_p( p ) );
        p_w_p( p ) = p_w;
        // Eq. 2 integrated over the step: (1 - n) V is constant.
        n_p( p ) = 1.0 - ( 1.0 - n ) / kinematics.volumeRatio( L );
        if ( !saturated )
        {
            const physics::RetentionState state = retention.state( p_w );
            S_p( p ) = state.S;
            dS_dp_p( p ) = state.dS_dp;
            k_rel_p( p ) = state.k_rel;
        }
    }
};

//! PorePressurePointUpdate of the points of `wv` (conditions as there).
template <class ExecSpace, class PressureView, class RateView, class FlagView>
PorePressurePointUpdate<ExecSpace, PressureView, RateView, FlagView>
porePressurePointUpdate( const WaterParticleViews<ExecSpace>& wv,
                         const physics::WaterParams& water, const double dt,
                         const bool saturated, const bool retention_current,
                         const PressureView& prescribed_p_w,
                         const RateView& inflow_rate,
                         const FlagView& inflow_ponding )
{
    return { physics::Kinematics{ dt },
             water,
             saturated,
             retention_current,
             wv.p_w_p,
             wv.S_p,
             wv.dS_dp_p,
             wv.k_rel_p,
             wv.n_p,
             wv.p_w_condition_p,
             wv.inflow_p,
             prescribed_p_w,
             inflow_rate,
             inflow_ponding };
}

} // namespace mpm

#endif // MPM_PORE_PRESSURE_HPP
