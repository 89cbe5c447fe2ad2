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
    int point;            //!< the point's index
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

    //! No water in transit adds to the solve's source.
    KOKKOS_INLINE_FUNCTION double transitSource( const int, const double ) const
    {
        return 0.0;
    }

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

//---------------------------------------------------------------------------//
/*!
  \brief The quasi-static scheme's flow increment (docs/formulation.md §11):
  the pressure solve's increment dp_c of the point's cell, solved with the
  fixed-stress storage. Besides what its p_w stores, the point took in
  its skeleton storage b dp (the water for the swelling of the skeleton the
  relaxation then makes) and gave up its water in transit (the last
  relaxation's difference, a source of the solve): the seepage the grid
  brought is their sum, and b dp V goes to anticipated_p (m^3 per metre).
*/
template <class ExecSpace>
struct FixedStressCellIncrement
{
    static constexpr bool needs_water_rate = false;
    using scalar_view =
        UnmanagedView<Kokkos::View<double*, DeviceType<ExecSpace>>>;

    CellPressureIncrement<ExecSpace> cell;
    scalar_view skeleton_storage_p; //!< b, 1/Pa
    scalar_view transit_p;          //!< water in transit, m^3 per metre
    scalar_view anticipated_p;      //!< out: b dp V, m^3 per metre
    scalar_view vol_p;              //!< point volumes, m^3 per metre

    //! The water in transit as a source of the solve over the step dt, 1/s.
    KOKKOS_INLINE_FUNCTION double transitSource( const int q,
                                                 const double dt ) const
    {
        return transit_p( q ) / ( vol_p( q ) * dt );
    }

    KOKKOS_INLINE_FUNCTION bool given( const int q, double& dp ) const
    {
        return cell.given( q, dp );
    }

    //! The stored change n (S - S0) + n S0 dp / K_w, and the seepage that
    //! brought it, the skeleton's b dp and less the water in transit.
    KOKKOS_INLINE_FUNCTION PointWaterChange
    water( const PointPressureStep& step ) const
    {
        const int q = step.point;
        const double dp = step.p_w_free - step.p_w0;
        const double skeleton = skeleton_storage_p( q ) * dp;
        anticipated_p( q ) = skeleton * vol_p( q );
        const double change = step.n * ( step.S - step.S0 ) + step.storage * dp;
        const double brought = change + skeleton - transit_p( q ) / vol_p( q );
        return { change,
                 step.source - brought / step.dt - step.S0 * step.div_v_s };
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The quasi-static scheme's relaxation (docs/formulation.md §11):
  every point keeps its p_w while the skeleton moves to equilibrium; the
  change of its stored water with its pore volume is water in transit,
  which the scheme books itself (pointWaterInTransit), so the step books none.
*/
struct HeldPorePressure
{
    static constexpr bool needs_water_rate = false;

    KOKKOS_INLINE_FUNCTION bool given( const int, double& dp ) const
    {
        dp = 0.0;
        return true;
    }

    //! Nothing stored, nothing brought (the inflow's source balanced).
    KOKKOS_INLINE_FUNCTION PointWaterChange
    water( const PointPressureStep& step ) const
    {
        return { 0.0, step.source };
    }
};

} // namespace mpm

#endif // MPM_PORE_PRESSURE_INCREMENTS_HPP
