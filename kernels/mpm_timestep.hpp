#ifndef MPM_TIMESTEP_HPP
#define MPM_TIMESTEP_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_wave_speeds.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
//! Result of the CFL reduction.
struct WaveSpeedLimit
{
    double dt_limit;       //!< min over points of h / (c_p + |v_p|), s
    double max_wave_speed; //!< max over points of c_p, m/s
};

//---------------------------------------------------------------------------//
//! The fastest wave of a dry point: the P wave, c_p = sqrt(E_c / rho_p),
//! rho_p = m_p / vol_p, E_c at the point's volume (physics::waveSpeedDry).
//! In a two-phase scene, rho_p = m_p / V the solid mass per unit volume:
//! the skeleton's P wave, which limits the semi-implicit step (the water's
//! stiffness in its pressure solve; the water's inertia left out, the
//! faster bound).
template <class ExecSpace>
struct DryWaveSpeed
{
    typename ParticleViews<ExecSpace>::unmanaged_type points;

    explicit DryWaveSpeed( const ParticleViews<ExecSpace>& pv )
        : points( unmanaged( pv ) )
    {
    }

    KOKKOS_INLINE_FUNCTION double
    operator()( const int p, const physics::MaterialParams& params ) const
    {
        return physics::waveSpeedDry( params, points.m_p( p ),
                                      points.vol_p( p ), points.vol0_p( p ) );
    }
};

/*!
  \brief The fastest wave of a two-phase point: with the drag implicit, the
  undrained mixture wave or the pore-water wave (physics::waveSpeedTwoPhase).
  The unsaturated storage dS/dp_w is left out (the stiffest fluid state):
  a point near saturation can re-wet within a step, and its fluid
  stiffness then jumps by orders of magnitude (Liakopoulos: 100-fold
  between p_w = -500 Pa and 0), which a step sized on the softer state
  does not survive.
*/
template <class ExecSpace>
struct TwoPhaseWaveSpeed
{
    typename ParticleViews<ExecSpace>::unmanaged_type points;
    typename WaterParticleViews<ExecSpace>::unmanaged_type water_points;
    physics::WaterParams water;

    TwoPhaseWaveSpeed( const ParticleViews<ExecSpace>& pv,
                       const WaterParticleViews<ExecSpace>& wv,
                       const physics::WaterParams& water_params )
        : points( unmanaged( pv ) )
        , water_points( unmanaged( wv ) )
        , water( water_params )
    {
    }

    KOKKOS_INLINE_FUNCTION double
    operator()( const int p, const physics::MaterialParams& params ) const
    {
        return physics::waveSpeedTwoPhase(
            params, water, points.m_p( p ), points.vol_p( p ),
            points.vol0_p( p ), water_points.n_p( p ), water_points.S_p( p ) );
    }
};

//! Adds point p's CFL limit h / (c_p + |v_p|) (Courant number 1,
//! physics::pointTimeStep) with c_p = wave_speed(p, params) to the
//! reduction's minimum step dt_min and largest wave speed c_max.
template <class WaveSpeed>
KOKKOS_INLINE_FUNCTION void
addPointLimit( const WaveSpeed& wave_speed, const int p,
               const physics::MaterialParams& params, const double cell_size,
               double& dt_min, double& c_max )
{
    const double c = wave_speed( p, params );
    const double dt =
        physics::pointTimeStep( cell_size, c, wave_speed.points.v_p( p, 0 ),
                                wave_speed.points.v_p( p, 1 ) );
    dt_min = dt < dt_min ? dt : dt_min;
    c_max = c > c_max ? c : c_max;
}

//---------------------------------------------------------------------------//
//! CFL reduction over the active points (addPointLimit): the minimum of
//! their stable steps and the largest wave speed.
template <class ExecSpace, class WaveSpeed>
WaveSpeedLimit
pointWaveSpeedLimit( const char* label, const ExecSpace& exec_space,
                     const ParticleViews<ExecSpace>& pv,
                     const physics::MaterialTable& materials,
                     const double cell_size, const WaveSpeed& wave_speed )
{
    const auto points = unmanaged( pv );
    WaveSpeedLimit limit{ 0.0, 0.0 };
    Kokkos::parallel_reduce(
        label, Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& dt_min, double& c_max ) {
            if ( points.status_p( p ) == point_active )
                addPointLimit( wave_speed, p, materials[points.material_p( p )],
                               cell_size, dt_min, c_max );
        },
        Kokkos::Min<double>( limit.dt_limit ),
        Kokkos::Max<double>( limit.max_wave_speed ) );
    return limit;
}

//! CFL reduction of a dry scene, or of a two-phase scene's skeleton
//! (DryWaveSpeed).
template <class ExecSpace>
WaveSpeedLimit criticalTimeStep( const ExecSpace& exec_space,
                                 const ParticleViews<ExecSpace>& pv,
                                 const physics::MaterialTable& materials,
                                 const double cell_size )
{
    return pointWaveSpeedLimit( "mpm::critical_time_step", exec_space, pv,
                                materials, cell_size,
                                DryWaveSpeed<ExecSpace>( pv ) );
}

//! CFL reduction of a two-phase scene (TwoPhaseWaveSpeed: the undrained
//! mixture or pore-water wave).
template <class ExecSpace>
WaveSpeedLimit criticalTimeStepTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double cell_size )
{
    return pointWaveSpeedLimit( "mpm::critical_time_step_two_phase", exec_space,
                                pv, materials, cell_size,
                                TwoPhaseWaveSpeed<ExecSpace>( pv, wv, water ) );
}

} // namespace mpm

#endif // MPM_TIMESTEP_HPP
