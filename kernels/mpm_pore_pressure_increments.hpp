#ifndef MPM_PORE_PRESSURE_INCREMENTS_HPP
#define MPM_PORE_PRESSURE_INCREMENTS_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_point_water.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! What a point's pore-pressure update did to its water over the step, per
//! unit volume (physics::addPointStepWater's volume_change and
//! flux_divergence).
struct PointWaterChange
{
    double volume_change;   //!< change of the water the point holds
    double flux_divergence; //!< div q of the seepage the grid brings in
};

//! The state of one point's pore-pressure update that the increment rules
//! need to book its water (PorePressurePointUpdate).
struct PointPressureStep
{
    double n;             //!< porosity at the step's start
    double S0;            //!< saturation at the step's start
    double S;             //!< saturation after the step
    double storage;       //!< n S0 / K_w, 1/Pa
    double p_w0;          //!< p_w at the step's start, Pa
    double p_w_free;      //!< p_w before ponding or a prescribed value, Pa
    double volume_change; //!< Eq. 8's dt (source - r)
    double water_rate;    //!< r = n S div v_w + (1 - n) S div v_s, 1/s
    double source;        //!< the inflow's Eq. 8 source, 1/s
    double div_v_s;       //!< solid divergence, 1/s
    double dt;            //!< step, s
};

//---------------------------------------------------------------------------//
/*!
  \brief The explicit scheme's pore-pressure increment: Eq. 8 at each point
  over the step, from the water volume rate r the point loop forms (the
  point's Newton on its retention law; the explicit increment
  K_w dt (source - r) / n when saturated).
*/
struct PointWaterBalance
{
    //! The point loop forms r = n S div v_w + (1 - n) S div v_s.
    static constexpr bool needs_water_rate = true;

    //! No increment is given: Eq. 8 at the point finds it.
    KOKKOS_INLINE_FUNCTION bool given( const int, double& ) const
    {
        return false;
    }

    //! Eq. 8's own balance: the change dt (source - r), the seepage
    //! r - S0 div v_s.
    KOKKOS_INLINE_FUNCTION PointWaterChange
    water( const PointPressureStep& step ) const
    {
        return { step.volume_change, step.water_rate - step.S0 * step.div_v_s };
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The semi-implicit scheme's pore-pressure increment
  (docs/formulation.md §9): the pressure solve's increment dp_c of the
  point's cell at its start-of-step position (the point loop reads x_p
  before it moves the point).
*/
template <class ExecSpace>
struct CellPressureIncrement
{
    //! The solve took the water volume rate at the predictor.
    static constexpr bool needs_water_rate = false;

    UnmanagedView<Kokkos::View<double**, DeviceType<ExecSpace>>> dp_c;
    UnmanagedView<typename ParticleViews<ExecSpace>::vector_view> x_p;
    physics::GridGeometry grid;

    //! dp = dp_c of point q's cell (0 outside the grid).
    KOKKOS_INLINE_FUNCTION bool given( const int q, double& dp ) const
    {
        int ci, cj;
        dp = grid.cellOf( x_p( q, 0 ), x_p( q, 1 ), ci, cj ) ? dp_c( ci, cj )
                                                             : 0.0;
        return true;
    }

    //! What the solve gave the point's water, n (S - S0) + n S0 dp / K_w,
    //! and the seepage that balances it, source - change / dt - S0 div v_s.
    KOKKOS_INLINE_FUNCTION PointWaterChange
    water( const PointPressureStep& step ) const
    {
        const double change = step.n * ( step.S - step.S0 ) +
                              step.storage * ( step.p_w_free - step.p_w0 );
        return { change,
                 step.source - change / step.dt - step.S0 * step.div_v_s };
    }
};

} // namespace mpm

#endif // MPM_PORE_PRESSURE_INCREMENTS_HPP
