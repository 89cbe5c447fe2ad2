#ifndef MPM_POINT_UPDATE_HPP
#define MPM_POINT_UPDATE_HPP

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
};

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of a step, one pass over the points:
  `update_state(p, params)` (velocity gradient, pore pressure, stress),
  then the position update x_p += du_p (a point that left the grid is
  removed with `remove_outside`, else reported), then the diagnostics of
  the new state (StepDiagnostics; `wave_speed(p, params)` is the point's
  fastest wave speed).
*/
template <class ExecSpace, class StateUpdate, class WaveSpeed>
PointUpdateReport
updatePoints( const char* label, const ExecSpace& exec_space,
              const ParticleViews<ExecSpace>& pv,
              const WaterParticleViews<ExecSpace>& wv,
              const physics::MaterialTable& materials,
              const physics::GridGeometry& grid, const bool remove_outside,
              const StateUpdate& update_state, const WaveSpeed& wave_speed )
{
    const PointSoundness<ExecSpace> sound( pv, wv );
    const auto x_p = pv.x_p;
    const auto du_p = pv.du_p;
    const auto v_p = pv.v_p;
    const auto m_p = pv.m_p;
    const auto material_p = pv.material_p;
    const auto status_p = pv.status_p;
    const double cell_size = grid.h;
    const int none = pv.size();
    StepDiagnostics d{ 0.0, 0.0, 0.0, 0.0, none };
    int first_outside = none;
    int num_removed = 0;

    Kokkos::parallel_reduce(
        label, Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& dt_min, double& c_max,
                       double& energy, double& speed2_max, int& first_unsound,
                       int& first_out, int& removed ) {
            if ( status_p( p ) != point_active )
                return;
            const physics::MaterialParams& params = materials[material_p( p )];
            update_state( p, params );
            if ( movePoint( p, x_p, du_p, grid ) )
            {
                if ( remove_outside )
                {
                    status_p( p ) = point_removed;
                    ++removed;
                    return;
                }
                if ( p < first_out )
                    first_out = p;
            }
            // Diagnostics of the new state.
            const double c = wave_speed( p, params );
            const double dt =
                pointTimeStep( cell_size, c, v_p( p, 0 ), v_p( p, 1 ) );
            dt_min = dt < dt_min ? dt : dt_min;
            c_max = c > c_max ? c : c_max;
            energy += 0.5 * m_p( p ) *
                      ( v_p( p, 0 ) * v_p( p, 0 ) + v_p( p, 1 ) * v_p( p, 1 ) );
            const double speed2 =
                v_p( p, 0 ) * v_p( p, 0 ) + v_p( p, 1 ) * v_p( p, 1 );
            if ( !sound( p, speed2 ) )
                first_unsound = p < first_unsound ? p : first_unsound;
            else
                speed2_max = speed2 > speed2_max ? speed2 : speed2_max;
        },
        Kokkos::Min<double>( d.dt_limit ),
        Kokkos::Max<double>( d.max_wave_speed ),
        Kokkos::Sum<double>( d.kinetic_energy ),
        Kokkos::Max<double>( d.max_speed2 ),
        Kokkos::Min<int>( d.first_unsound ), Kokkos::Min<int>( first_outside ),
        Kokkos::Sum<int>( num_removed ) );
    return PointUpdateReport{ first_outside >= none ? -1 : first_outside,
                              num_removed, d };
}

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of the dry step (updatePoints): velocity
  gradient from the remapped nodal velocity (with `bbar`: the gradient of
  velocityGradientCellSums with its cell-averaged volumetric part), stress
  update, position update and diagnostics.
*/
template <class ExecSpace>
PointUpdateReport updatePointsDry( const ExecSpace& exec_space,
                                   const ParticleViews<ExecSpace>& pv,
                                   const GridViews<ExecSpace>& gv,
                                   const physics::MaterialTable& materials,
                                   const double dt, const bool bbar,
                                   const bool remove_outside )
{
    const StressPointUpdate<ExecSpace> stress( pv, dt );
    const auto grid = gv.geometry;
    const auto v_i = gv.v_i;
    const auto vol_c = gv.vol_c;
    const auto dvol_c = gv.dvol_c;
    const auto x_p = pv.x_p;
    const auto grad_v_p = pv.grad_v_p;
    const auto m_p = pv.m_p;
    const auto vol_p = pv.vol_p;

    const auto update_state =
        KOKKOS_LAMBDA( const int p, const physics::MaterialParams& params )
    {
        double L[2][2];
        if ( bbar )
        {
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    L[a][b] = grad_v_p( p, a, b );
            int ci, cj;
            if ( grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
            {
                cellAverageVolumetricRate( ci, cj, vol_c, dvol_c, L );
                grad_v_p( p, 0, 0 ) = L[0][0];
                grad_v_p( p, 1, 1 ) = L[1][1];
            }
        }
        else
        {
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            gradientAt( ci, cj, dwdx, dwdy, v_i, L );
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    grad_v_p( p, a, b ) = L[a][b];
        }
        stress( p, L, params );
    };
    const auto wave_speed =
        KOKKOS_LAMBDA( const int p, const physics::MaterialParams& params )
    {
        return waveSpeedDry( params, m_p( p ), vol_p( p ) );
    };
    return updatePoints( "mpm::update_points_dry", exec_space, pv,
                         WaterParticleViews<ExecSpace>(), materials, grid,
                         remove_outside, update_state, wave_speed );
}

//---------------------------------------------------------------------------//
/*!
  \brief The last point loop of the two-phase step (updatePoints): solid
  velocity gradient and water divergence (waterDivergenceAt) from the
  remapped nodal velocities (with `bbar`: those of
  velocityGradientCellSums with their cell averages), pore pressure,
  porosity and retention state (`pore_pressure`, PorePressurePointUpdate),
  stress, position update and diagnostics.
*/
template <class ExecSpace, class PorePressureUpdate>
PointUpdateReport updatePointsTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const GridViews<ExecSpace>& gv,
    const WaterGridViews<ExecSpace>& wg,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double dt, const bool bbar, const bool remove_outside,
    const PorePressureUpdate& pore_pressure )
{
    const StressPointUpdate<ExecSpace> stress( pv, dt );
    const auto grid = gv.geometry;
    const auto v_s_i = gv.v_i;
    const auto v_w_i = wg.v_w_i;
    const auto m_w_i = wg.m_w_i;
    const auto vol_i = wg.vol_i;
    const auto vol_c = gv.vol_c;
    const auto dvol_c = gv.dvol_c;
    const auto div_w_c = wg.div_w_c;
    const auto x_p = pv.x_p;
    const auto grad_v_p = pv.grad_v_p;
    const auto m_p = pv.m_p;
    const auto vol_p = pv.vol_p;
    const auto div_v_w_p = wv.div_v_w_p;
    const auto n_p = wv.n_p;
    const auto S_p = wv.S_p;
    const double water_density = water.density;

    const auto update_state =
        KOKKOS_LAMBDA( const int p, const physics::MaterialParams& params )
    {
        double L[2][2];
        double div_v_w;
        if ( bbar )
        {
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    L[a][b] = grad_v_p( p, a, b );
            div_v_w = div_v_w_p( p );
            int ci, cj;
            if ( grid.cellOf( x_p( p, 0 ), x_p( p, 1 ), ci, cj ) )
            {
                cellAverageVolumetricRate( ci, cj, vol_c, dvol_c, L );
                grad_v_p( p, 0, 0 ) = L[0][0];
                grad_v_p( p, 1, 1 ) = L[1][1];
                div_v_w = div_w_c( ci, cj ) / vol_c( ci, cj );
                div_v_w_p( p ) = div_v_w;
            }
        }
        else
        {
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            gradientAt( ci, cj, dwdx, dwdy, v_s_i, L );
            for ( int a = 0; a < 2; ++a )
                for ( int b = 0; b < 2; ++b )
                    grad_v_p( p, a, b ) = L[a][b];
            div_v_w = waterDivergenceAt( ci, cj, dwdx, dwdy, v_s_i, v_w_i,
                                         m_w_i, vol_i, water_density,
                                         n_p( p ) * S_p( p ), L );
            div_v_w_p( p ) = div_v_w;
        }
        pore_pressure( p, L, div_v_w, params );
        stress( p, L, params );
    };
    const auto wave_speed =
        KOKKOS_LAMBDA( const int p, const physics::MaterialParams& params )
    {
        return waveSpeedTwoPhase( params, water, m_p( p ), vol_p( p ), n_p( p ),
                                  S_p( p ) );
    };
    return updatePoints( "mpm::update_points_two_phase", exec_space, pv, wv,
                         materials, grid, remove_outside, update_state,
                         wave_speed );
}

} // namespace mpm

#endif // MPM_POINT_UPDATE_HPP
