#ifndef MPM_PORE_PRESSURE_HPP
#define MPM_PORE_PRESSURE_HPP

#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure_increments.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_kinematics.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_point_water.hpp>
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
  \brief Pore pressure, porosity and retention state of points
  (docs/formulation.md steps 6, 7, 9) from their velocity gradient L and water
  volume rate r = n S div v_w + (1 - n) S div v_s (waterVolumeRate): p_w from
  the mass-conservative Eq. 8 (explicit when saturated), prescribed point
  pressures, porosity from Eq. 2 as n' = 1 - (1 - n) / det(I + L dt), then S,
  dS/dp_w, k_rel. `prescribed_p_w(c)` is the current pressure of condition c,
  Pa, unless `prescribed_hold(c)`: then its points keep p_w_held_p (their p_w
  at the stage start); `inflow_rate(f)` the water volume inflow f adds per
  unit initial point volume (vol0_p) and time (1/s), times the point's
  inflow_weight_p, a source in Eq. 8 (so V source is exactly the point's share
  of the prescribed rain however its volume changed); `inflow_ponding(f)` caps
  p_w at 0 on its points (the excess runs off). With `retention_current`, the
  stored S_p, dS_dp_p and k_rel_p are the retention law's values at p_w_p
  (true after an unsaturated update with the same materials), which saves one
  retention evaluation per point, and all of them where p_w is held. Updates
  up to `lanes` points at once, their Newton iterations in lock step
  (physics::porePressureIncrements), and adds the water they took in, ran off
  or were given to `volumes` (physics::addPointStepWater; the point volumes
  are those at the step's start). `Increment` is the scheme's rule for the
  increment and its water (PointWaterBalance: Eq. 8 at the point;
  CellPressureIncrement: the pressure solve's increment of the point's
  cell, docs/formulation.md §9).
*/
template <class ExecSpace, class PressureView, class RateView, class FlagView,
          class Increment>
struct PorePressurePointUpdate
{
    static constexpr int lanes = 4;
    using increment_type = Increment;
    using wv_type = WaterParticleViews<ExecSpace>;
    using scalar_view = UnmanagedView<typename wv_type::scalar_view>;
    using int_view = UnmanagedView<typename wv_type::int_view>;
    physics::Kinematics kinematics;
    physics::WaterParams water;
    bool saturated;
    bool retention_current;
    scalar_view p_w_p, S_p, dS_dp_p, k_rel_p, n_p, p_w_held_p, inflow_weight_p,
        vol_p, vol0_p;
    int_view condition_p, inflow_p;
    UnmanagedView<PressureView> prescribed_p_w;
    UnmanagedView<FlagView> prescribed_hold;
    UnmanagedView<RateView> inflow_rate;
    UnmanagedView<FlagView> inflow_ponding;
    Increment increment;

    //! Water volume inflow `inflow` adds to point q per unit volume, 1/s.
    KOKKOS_INLINE_FUNCTION double inflowSource( const int q,
                                                const int inflow ) const
    {
        return inflow >= 0 ? physics::inflowSource( inflow_rate( inflow ),
                                                    inflow_weight_p( q ),
                                                    vol0_p( q ), vol_p( q ) )
                           : 0.0;
    }

    //! Updates the `count` (<= lanes) points p[l], with velocity gradient
    //! L[l], water volume rate water_rate[l] and material params[l].
    KOKKOS_INLINE_FUNCTION void
    operator()( const int count, const int p[], const double L[][2][2],
                const double water_rate[],
                const physics::MaterialParams* const params[],
                physics::WaterStepVolumes& volumes ) const
    {
        RetentionAt retention[lanes];
        physics::PorePressureNewton newton[lanes];
        physics::SaturationState stored[lanes];
        double source[lanes]; // the inflow's Eq. 8 source, 1/s
        bool given[lanes];    // the increment came from the rule
        for ( int l = 0; l < lanes; ++l )
        {
            newton[l].done = true;
            if ( l >= count )
                continue;
            const int q = p[l];
            const double n = n_p( q );
            const double S = S_p( q );
            // Water volume change per unit volume over the step (Eq. 8).
            source[l] = inflowSource( q, inflow_p( q ) );
            const double volume_change =
                kinematics.dt * ( source[l] - water_rate[l] );
            retention[l] = RetentionAt{ params[l]->retention };
            newton[l] = physics::PorePressureNewton(
                p_w_p( q ), S, n, water.bulk_modulus, volume_change );
            stored[l] = physics::SaturationState{ S, dS_dp_p( q ) };
            // Explicit when saturated; a prescribed p_w replaces the
            // increment; or the rule gives it.
            given[l] = increment.given( q, newton[l].dp );
            newton[l].done = saturated || condition_p( q ) >= 0 || given[l];
        }
        physics::porePressureIncrements( retention, newton, stored,
                                         retention_current );
        for ( int l = 0; l < count; ++l )
        {
            const int q = p[l];
            const physics::PorePressureNewton& point = newton[l];
            const int inflow = inflow_p( q );
            const int condition = condition_p( q );
            const bool prescribed = condition >= 0;
            const physics::PointPressure after =
                physics::pointPressureAfterStep(
                    point.p_w, point.dp, point.volume_change, point.n,
                    water.bulk_modulus, saturated && !given[l],
                    inflow >= 0 && inflow_ponding( inflow ), prescribed,
                    !prescribed ? 0.0
                    : prescribed_hold( condition )
                        ? p_w_held_p( q )
                        : prescribed_p_w( condition ) );
            const double p_w = after.p_w;
            p_w_p( q ) = p_w;
            n_p( q ) = physics::porosityAfterStep(
                point.n, kinematics.volumeRatio( L[l] ) );
            // The stored state is current at an unchanged p_w (held points).
            if ( !saturated && !( retention_current && p_w == point.p_w ) )
            {
                const physics::RetentionState state = retention[l].state( p_w );
                S_p( q ) = state.S;
                dS_dp_p( q ) = state.dS_dp;
                k_rel_p( q ) = state.k_rel;
            }
            const PointWaterChange change = increment.water(
                { point.n, point.S, S_p( q ), point.storage, point.p_w,
                  after.p_w_free, point.volume_change, water_rate[l], source[l],
                  L[l][0][0] + L[l][1][1], kinematics.dt, q } );
            physics::addPointStepWater(
                volumes, vol_p( q ), kinematics.dt, source[l],
                change.flux_divergence, change.volume_change, point.storage,
                after.capped, after.p_w_free, prescribed, point.n, point.S,
                S_p( q ), point.p_w, p_w );
        }
    }
};

//! PorePressurePointUpdate of the points of `wv` (conditions as there)
//! with the scheme's increment rule.
template <class ExecSpace, class PressureView, class RateView, class FlagView,
          class Increment>
PorePressurePointUpdate<ExecSpace, PressureView, RateView, FlagView, Increment>
porePressurePointUpdate(
    const ParticleViews<ExecSpace>& pv, const WaterParticleViews<ExecSpace>& wv,
    const physics::WaterParams& water, const double dt, const bool saturated,
    const bool retention_current, const PressureView& prescribed_p_w,
    const FlagView& prescribed_hold, const RateView& inflow_rate,
    const FlagView& inflow_ponding, const Increment& increment )
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
             wv.p_w_held_p,
             wv.inflow_weight_p,
             pv.vol_p,
             pv.vol0_p,
             wv.p_w_condition_p,
             wv.inflow_p,
             prescribed_p_w,
             prescribed_hold,
             inflow_rate,
             inflow_ponding,
             increment };
}

} // namespace mpm

#endif // MPM_PORE_PRESSURE_HPP
