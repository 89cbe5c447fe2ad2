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
/*!
  \brief CFL reduction: the P-wave speed of each point,
  c_p = sqrt(E_c / rho_p), rho_p = m_p / vol_p, gives the stable step
  h / (c_p + |v_p|) (Courant number 1); returns its minimum and max c_p.
*/
template <class ExecSpace>
WaveSpeedLimit criticalTimeStep( const ExecSpace& exec_space,
                                 const ParticleViews<ExecSpace>& pv,
                                 const physics::MaterialTable& materials,
                                 const double cell_size )
{
    const auto v_p = unmanaged( pv.v_p );
    const auto m_p = unmanaged( pv.m_p );
    const auto vol_p = unmanaged( pv.vol_p );
    const auto material_p = unmanaged( pv.material_p );
    const auto status_p = unmanaged( pv.status_p );
    WaveSpeedLimit limit{ 0.0, 0.0 };
    Kokkos::parallel_reduce(
        "mpm::critical_time_step",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& dt_min, double& c_max ) {
            if ( status_p( p ) != point_active )
                return;
            const double c = physics::waveSpeedDry( materials[material_p( p )],
                                                    m_p( p ), vol_p( p ) );
            const double dt = physics::pointTimeStep( cell_size, c, v_p( p, 0 ),
                                                      v_p( p, 1 ) );
            dt_min = dt < dt_min ? dt : dt_min;
            c_max = c > c_max ? c : c_max;
        },
        Kokkos::Min<double>( limit.dt_limit ),
        Kokkos::Max<double>( limit.max_wave_speed ) );
    return limit;
}

//---------------------------------------------------------------------------//
/*!
  \brief CFL reduction of a two-phase scene: with the drag implicit the
  limit is the fastest wave, the undrained mixture wave or the pore-water
  wave of each point (physics::twoPhaseWaveSpeed), h / (c_p + |v_s|).
  The unsaturated storage dS/dp_w is left out (the stiffest fluid state):
  a point near saturation can re-wet within a step, and its fluid
  stiffness then jumps by orders of magnitude (Liakopoulos: 100-fold
  between p_w = -500 Pa and 0), which a step sized on the softer state
  does not survive.
*/
template <class ExecSpace>
WaveSpeedLimit criticalTimeStepTwoPhase(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const double cell_size )
{
    const auto v_p = unmanaged( pv.v_p );
    const auto m_p = unmanaged( pv.m_p );
    const auto vol_p = unmanaged( pv.vol_p );
    const auto material_p = unmanaged( pv.material_p );
    const auto status_p = unmanaged( pv.status_p );
    const auto n_p = unmanaged( wv.n_p );
    const auto S_p = unmanaged( wv.S_p );
    WaveSpeedLimit limit{ 0.0, 0.0 };
    Kokkos::parallel_reduce(
        "mpm::critical_time_step_two_phase",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& dt_min, double& c_max ) {
            if ( status_p( p ) != point_active )
                return;
            const double c = physics::waveSpeedTwoPhase(
                materials[material_p( p )], water, m_p( p ), vol_p( p ),
                n_p( p ), S_p( p ) );
            const double dt = physics::pointTimeStep( cell_size, c, v_p( p, 0 ),
                                                      v_p( p, 1 ) );
            dt_min = dt < dt_min ? dt : dt_min;
            c_max = c > c_max ? c : c_max;
        },
        Kokkos::Min<double>( limit.dt_limit ),
        Kokkos::Max<double>( limit.max_wave_speed ) );
    return limit;
}

} // namespace mpm

#endif // MPM_TIMESTEP_HPP
