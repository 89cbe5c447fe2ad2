#ifndef MPM_POINT_STATE_COPY_HPP
#define MPM_POINT_STATE_COPY_HPP

#include <mpm_device_type.hpp>
#include <solver/mpm_simulation_state.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief A copy of every point field of a simulation (the solid's and, in a
  two-phase scene, the water's and the cells' last pressure increments, the
  next pressure solve's start), on the device: the seepage and quasi-static
  schemes keep the state at a step's start to go back to it when the step
  is given back (its flow changed a saturation too much, or, in the auto
  scheme, its skeleton found no equilibrium).
*/
template <class ExecSpace>
class PointStateCopy
{
  public:
    explicit PointStateCopy( const SimulationState<ExecSpace>& state )
        : _particles( state.particles.size() )
    {
        if ( !state.water_particles.allocated() )
            return;
        _water = WaterParticleViews<ExecSpace>( state.particles.size() );
        _dp_w_c = Kokkos::View<double**, DeviceType<ExecSpace>>(
            "saved_dp_w_c", state.water_grid.dp_w_c.extent( 0 ),
            state.water_grid.dp_w_c.extent( 1 ) );
    }

    //! Keeps `state`'s point fields.
    void save( const SimulationState<ExecSpace>& state )
    {
        copyViews( state.particles, _particles );
        if ( !_water.allocated() )
            return;
        copyViews( state.water_particles, _water );
        Kokkos::deep_copy( _dp_w_c, state.water_grid.dp_w_c );
    }

    //! Gives `state` back the point fields kept by save; what derives from
    //! them is recomputed (stateChanged).
    void restore( SimulationState<ExecSpace>& state ) const
    {
        copyViews( _particles, state.particles );
        state.stateChanged();
        if ( !_water.allocated() )
            return;
        copyViews( _water, state.water_particles );
        Kokkos::deep_copy( state.water_grid.dp_w_c, _dp_w_c );
    }

  private:
    ParticleViews<ExecSpace> _particles;
    WaterParticleViews<ExecSpace> _water;
    Kokkos::View<double**, DeviceType<ExecSpace>> _dp_w_c;
};

} // namespace mpm

#endif // MPM_POINT_STATE_COPY_HPP
