#ifndef MPM_POINT_UPDATE_HPP
#define MPM_POINT_UPDATE_HPP

#include <mpm_base_cells.hpp>
#include <mpm_diagnostics.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_position_update.hpp>
#include <mpm_stress_update.hpp>
#include <mpm_timestep.hpp>
#include <mpm_velocity_gradient.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_point_water.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Outcome of the last point loop of a step.
struct PointUpdateReport
{
    int first_outside; //!< smallest index of a point that left the grid
                       //!< and was kept, -1 if none
    int num_removed;   //!< points removed because they left the grid
    StepDiagnostics diagnostics; //!< of the new state
    //! Two-phase: the water the step's Eq. 8 moved (zero when dry).
    physics::WaterStepVolumes water;
};

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of a step, one pass over the points in groups
  of GroupSize: `update_states(count, p, params)` updates the state of the
  group's `count` active points p[0..count) of materials params[l]
  (velocity gradient, pore pressure, stress) and adds the water it moved to
  `volumes` (physics::WaterStepVolumes), then, point after point, the
  position, x_p += du_p (a point that left the grid is removed with
  `remove_outside`, else reported), and the diagnostics of the new state
  (StepDiagnostics; `wave_speed(p, params)` is the point's fastest wave
  speed; without `cfl_limit` the CFL limit and the largest wave speed are
  not reduced, dt_limit stays at the largest double and max_wave_speed 0:
  for a caller that takes them from a later loop).
*/
template <int GroupSize, class ExecSpace, class StateUpdate, class WaveSpeed>
PointUpdateReport updatePoints(
    const char* label, const ExecSpace& exec_space,
    const ParticleViews<ExecSpace>& pv, const WaterParticleViews<ExecSpace>& wv,
    const physics::MaterialTable& materials, const physics::GridGeometry& grid,
    const bool remove_outside, const StateUpdate& update_states,
    const WaveSpeed& wave_speed, const bool cfl_limit = true )
{
    const PointSoundness<ExecSpace> sound( pv, wv );
    const auto points = unmanaged( pv );
    const double cell_size = grid.h;
    const int none = pv.size();
    StepDiagnostics d{ 0.0, 0.0, 0.0, 0.0, none };
    int first_outside = none;
    int num_removed = 0;
    physics::WaterStepVolumes water;

    Kokkos::parallel_reduce(
        label,
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0,
                                        ( none + GroupSize - 1 ) / GroupSize ),
        KOKKOS_LAMBDA( const int group, double& dt_min, double& c_max,
                       double& energy, double& speed2_max, int& first_unsound,
                       int& first_out, int& removed, double& point_inflow,
                       double& runoff, double& prescribed, double& flow_in ) {
            // The group's active points.
            int p[GroupSize];
            const physics::MaterialParams* params[GroupSize];
            int count = 0;
            const int end = ( group + 1 ) * GroupSize < none
                                ? ( group + 1 ) * GroupSize
                                : none;
            for ( int q = group * GroupSize; q < end; ++q )
                if ( points.status_p( q ) == point_active )
                {
                    p[count] = q;
                    params[count] = &materials[points.material_p( q )];
                    ++count;
                }
            if ( count == 0 )
                return;
            physics::WaterStepVolumes volumes;
            update_states( count, p, params, volumes );
            point_inflow += volumes.point_inflow;
            runoff += volumes.runoff;
            prescribed += volumes.prescribed;
            flow_in += volumes.flow_in;
            for ( int l = 0; l < count; ++l )
            {
                const int q = p[l];
                if ( movePoint( q, points.x_p, points.du_p, grid ) )
                {
                    if ( remove_outside )
                    {
                        points.status_p( q ) = point_removed;
                        ++removed;
                        continue;
                    }
                    if ( q < first_out )
                        first_out = q;
                }
                // Diagnostics of the new state.
                if ( cfl_limit )
                    addPointLimit( wave_speed, q, *params[l], cell_size, dt_min,
                                   c_max );
                const double speed2 = mpm::speed2( points, q );
                energy += 0.5 * points.m_p( q ) * speed2;
                if ( !sound( q, speed2 ) )
                    first_unsound = q < first_unsound ? q : first_unsound;
                else
                    speed2_max = speed2 > speed2_max ? speed2 : speed2_max;
            }
        },
        Kokkos::Min<double>( d.dt_limit ),
        Kokkos::Max<double>( d.max_wave_speed ),
        Kokkos::Sum<double>( d.kinetic_energy ),
        Kokkos::Max<double>( d.max_speed2 ),
        Kokkos::Min<int>( d.first_unsound ), Kokkos::Min<int>( first_outside ),
        Kokkos::Sum<int>( num_removed ),
        Kokkos::Sum<double>( water.point_inflow ),
        Kokkos::Sum<double>( water.runoff ),
        Kokkos::Sum<double>( water.prescribed ),
        Kokkos::Sum<double>( water.flow_in ) );
    return PointUpdateReport{ first_outside >= none ? -1 : first_outside,
                              num_removed, d, water };
}

//---------------------------------------------------------------------------//
/*!
  \brief The velocity gradient L of a point for the step's stress and pore
  pressure and (two-phase) its water volume rate r = n S div v_w + (1 - n)
  S div v_s (waterVolumeRate; div v_w from waterDivergenceAt), kept in
  grad_v_p (and div_v_w_p): from the remapped nodal velocities or, with
  `bbar`, the gradient of velocityGradientCellSums with the cell-averaged
  volumetric rates (cellAverageVolumetricRate, and the cell average of the
  water divergence). A point of a base cell adds the water its cell's
  empty part passes on (BaseCellAccess::extraRate). Without `water_rate`
  (a pore-pressure rule that does not use it: CellPressureIncrement, whose
  pressure solve took the predictor's rate r*) r is not formed: water_rate stays
  0 and div_v_w_p unchanged.
*/
template <class ExecSpace>
struct StepVelocityGradient
{
    using pv_type = ParticleViews<ExecSpace>;
    using wv_type = WaterParticleViews<ExecSpace>;
    using gv_type = GridViews<ExecSpace>;
    using wg_type = WaterGridViews<ExecSpace>;
    bool bbar;
    bool form_water_rate; //!< two-phase, and r is needed
    BaseCellAccess<ExecSpace> base;
    physics::GridGeometry grid;
    UnmanagedView<typename gv_type::vector_view> v_s_i;
    UnmanagedView<typename wg_type::vector_view> v_w_i;
    UnmanagedView<typename wg_type::scalar_view> nS_i, div_w_c;
    UnmanagedView<typename gv_type::scalar_view> vol_c, dvol_c;
    UnmanagedView<typename pv_type::vector_view> x_p;
    UnmanagedView<typename pv_type::gradient_view> grad_v_p;
    UnmanagedView<typename wv_type::scalar_view> div_v_w_p, n_p, S_p;

    StepVelocityGradient( const ParticleViews<ExecSpace>& pv,
                          const WaterParticleViews<ExecSpace>& wv,
                          const GridViews<ExecSpace>& gv,
                          const WaterGridViews<ExecSpace>& wg,
                          const bool cell_average,
                          const BaseCellAccess<ExecSpace>& base_cells,
                          const bool water_rate = true )
        : bbar( cell_average )
        , form_water_rate( wv.allocated() && water_rate )
        , base( base_cells )
        , grid( gv.geometry )
        , v_s_i( gv.v_i )
        , v_w_i( wg.v_w_i )
        , nS_i( wg.nS_i )
        , div_w_c( wg.div_w_c )
        , vol_c( gv.vol_c )
        , dvol_c( gv.dvol_c )
        , x_p( pv.x_p )
        , grad_v_p( pv.grad_v_p )
        , div_v_w_p( wv.div_v_w_p )
        , n_p( wv.n_p )
        , S_p( wv.S_p )
    {
    }

    //! L and (two-phase) the water volume rate r of point p.
    KOKKOS_FORCEINLINE_FUNCTION void operator()( const int p, double L[2][2],
                                                 double& water_rate ) const
    {
        water_rate = 0.0;
        double div_v_w = 0.0;
        if ( bbar )
        {
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    L[a][b] = grad_v_p( p, a, b );
            if ( form_water_rate )
                div_v_w = div_v_w_p( p );
            int ci, cj;
            if ( !grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
            {
                if ( form_water_rate )
                    water_rate = physics::waterVolumeRate( n_p( p ), S_p( p ),
                                                           div_v_w, L );
                return;
            }
            cellAverageVolumetricRate( ci, cj, vol_c, dvol_c, L );
            grad_v_p( p, 0, 0 ) = L[0][0];
            grad_v_p( p, 1, 1 ) = L[1][1];
            if ( form_water_rate )
            {
                div_v_w = div_w_c( ci, cj ) / vol_c( ci, cj );
                div_v_w_p( p ) = div_v_w;
                water_rate =
                    physics::waterVolumeRate( n_p( p ), S_p( p ), div_v_w, L ) +
                    base.extraRate( ci, cj );
            }
            return;
        }
        int ci, cj;
        double w[4], dwdx[4], dwdy[4];
        grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
        gradientAt( ci, cj, dwdx, dwdy, v_s_i, L );
        for ( int a = 0; a < 2; ++a )
            for ( int b = 0; b < 2; ++b )
                grad_v_p( p, a, b ) = L[a][b];
        if ( form_water_rate )
        {
            div_v_w = waterDivergenceAt( ci, cj, dwdx, dwdy, v_s_i, v_w_i, nS_i,
                                         n_p( p ) * S_p( p ), L );
            div_v_w_p( p ) = div_v_w;
            water_rate =
                physics::waterVolumeRate( n_p( p ), S_p( p ), div_v_w, L ) +
                base.extraRate( ci, cj );
        }
    }
};

//---------------------------------------------------------------------------//
//! The state update of the dry step (updatePoints): velocity gradient
//! (StepVelocityGradient) and stress of each point of a group.
template <class ExecSpace>
struct DryStateUpdate
{
    StepVelocityGradient<ExecSpace> gradient;
    StressPointUpdate<ExecSpace> stress;

    KOKKOS_FORCEINLINE_FUNCTION void
    operator()( const int count, const int p[],
                const physics::MaterialParams* const params[],
                physics::WaterStepVolumes& ) const
    {
        for ( int l = 0; l < count; ++l )
        {
            double L[2][2], water_rate;
            gradient( p[l], L, water_rate );
            stress( p[l], L, *params[l] );
        }
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of the dry step (updatePoints): velocity
  gradient, stress update, position update and diagnostics.
*/
template <class ExecSpace>
PointUpdateReport updatePointsDry( const ExecSpace& exec_space,
                                   const ParticleViews<ExecSpace>& pv,
                                   const GridViews<ExecSpace>& gv,
                                   const physics::MaterialTable& materials,
                                   const double dt, const bool bbar,
                                   const bool remove_outside )
{
    const WaterParticleViews<ExecSpace> no_water;
    const DryStateUpdate<ExecSpace> update_states{
        StepVelocityGradient<ExecSpace>(
            pv, no_water, gv, WaterGridViews<ExecSpace>(), bbar,
            BaseCellAccess<ExecSpace>( BaseCells<ExecSpace>(), gv.geometry ) ),
        StressPointUpdate<ExecSpace>( pv, dt ) };
    const DryWaveSpeed<ExecSpace> wave_speed( pv );
    return updatePoints<1>( "mpm::update_points_dry", exec_space, pv, no_water,
                            materials, gv.geometry, remove_outside,
                            update_states, wave_speed );
}

//---------------------------------------------------------------------------//
/*!
  \brief The state update of the two-phase step (updatePoints) of a group
  of up to PorePressureUpdate::lanes points: velocity gradient and water
  divergence (StepVelocityGradient), pore pressure, porosity and retention
  state (PorePressurePointUpdate, the whole group at once), stress.
*/
template <class ExecSpace, class PorePressureUpdate>
struct TwoPhaseStateUpdate
{
    static constexpr int lanes = PorePressureUpdate::lanes;
    StepVelocityGradient<ExecSpace> gradient;
    PorePressureUpdate pore_pressure;
    StressPointUpdate<ExecSpace> stress;

    KOKKOS_FORCEINLINE_FUNCTION void
    operator()( const int count, const int p[],
                const physics::MaterialParams* const params[],
                physics::WaterStepVolumes& volumes ) const
    {
        double L[lanes][2][2], water_rate[lanes];
        for ( int l = 0; l < count; ++l )
            gradient( p[l], L[l], water_rate[l] );
        pore_pressure( count, p, L, water_rate, params, volumes );
        for ( int l = 0; l < count; ++l )
            stress( p[l], L[l], *params[l] );
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of the two-phase step (updatePoints): velocity
  gradient, water divergence (if the pore-pressure rule needs the water
  volume rate), pore pressure (`pore_pressure`, PorePressurePointUpdate),
  stress, position update and diagnostics: the CFL limit of `wave_speed`
  (the scheme's fastest wave) only with `cfl_limit` (the cell water
  equilibrium, which changes S afterwards, reduces its own).
*/
template <class ExecSpace, class PorePressureUpdate, class WaveSpeed>
PointUpdateReport updatePointsTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg,
    const physics::MaterialTable& materials, const double dt, const bool bbar,
    const bool remove_outside, const PorePressureUpdate& pore_pressure,
    const BaseCellAccess<ExecSpace>& base, const WaveSpeed& wave_speed,
    const bool cfl_limit )
{
    const TwoPhaseStateUpdate<ExecSpace, PorePressureUpdate> update_states{
        StepVelocityGradient<ExecSpace>(
            pv, wv, gv, wg, bbar, base,
            PorePressureUpdate::increment_type::needs_water_rate ),
        pore_pressure, StressPointUpdate<ExecSpace>( pv, dt ) };
    return updatePoints<PorePressureUpdate::lanes>(
        "mpm::update_points_two_phase", exec_space, pv, wv, materials,
        gv.geometry, remove_outside, update_states, wave_speed, cfl_limit );
}

} // namespace mpm

#endif // MPM_POINT_UPDATE_HPP
