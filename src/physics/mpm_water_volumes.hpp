#ifndef MPM_WATER_VOLUMES_HPP
#define MPM_WATER_VOLUMES_HPP

#include <algorithm>
#include <cmath>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief The water one step of Eq. 8 moves, summed over points, m^3 per
  metre out of plane (water at its reference density). Each point's
  update n dS + (n S / K_w) dp_w = dt (source - div q - S div v_s)
  (PorePressureNewton) splits into these terms; the pore volume change
  S div v_s is the change of the stored water's pore space, not an
  exchange, and is carried by the stored volume itself
  (pointWaterVolume).
*/
struct WaterStepVolumes
{
    double point_inflow = 0.0; //!< added by inflows on points (the source)
    double runoff = 0.0;       //!< taken off by the ponding cap p_w <= 0
    double prescribed = 0.0;   //!< net added to hold prescribed p_w
    double flow_in = 0.0;      //!< net seepage into the points, -V div q dt
};

//---------------------------------------------------------------------------//
/*!
  \brief Water balance of a stage or a run, m^3 per metre out of plane:
  the stored water at its start and end (in the simulated points and in
  those removed after leaving the grid) against the sum of what the steps
  moved (WaterStepVolumes). The closure error is what the steps' terms do
  not explain: the Newton tolerance, the linearised storage and pore
  volume of Eq. 8 against the stored water's exact form, and any water a
  part of the step does not conserve.
*/
struct WaterBalance
{
    double stored_start = 0.0;      //!< in the simulated points
    double stored_end = 0.0;        //!< ... at the end
    double carried_off_start = 0.0; //!< in points removed from the grid
    double carried_off_end = 0.0;   //!< ... at the end
    double point_inflow = 0.0;
    double runoff = 0.0;
    double prescribed = 0.0;
    double flow_in = 0.0;

    //! Starts the ledger at the stored volumes of the points.
    void begin( const double stored, const double carried_off )
    {
        *this = WaterBalance();
        stored_start = stored_end = stored;
        carried_off_start = carried_off_end = carried_off;
    }

    //! Adds one step's terms.
    void addStep( const WaterStepVolumes& step )
    {
        point_inflow += step.point_inflow;
        runoff += step.runoff;
        prescribed += step.prescribed;
        flow_in += step.flow_in;
    }

    //! Closes the ledger at the stored volumes of the points.
    void end( const double stored, const double carried_off )
    {
        stored_end = stored;
        carried_off_end = carried_off;
    }

    //! Appends a later ledger (the next stage): its terms and its end.
    void append( const WaterBalance& later )
    {
        point_inflow += later.point_inflow;
        runoff += later.runoff;
        prescribed += later.prescribed;
        flow_in += later.flow_in;
        stored_end = later.stored_end;
        carried_off_end = later.carried_off_end;
    }

    //! Change of the water held by all points (removed ones included).
    double storedChange() const
    {
        return ( stored_end - stored_start ) +
               ( carried_off_end - carried_off_start );
    }

    //! The change of the stored water less what the steps moved.
    double closureError() const
    {
        return storedChange() -
               ( point_inflow - runoff + prescribed + flow_in );
    }

    //! |closureError()| over the largest term (0 if nothing moved).
    double relativeClosureError() const
    {
        const double largest =
            std::max( { std::fabs( storedChange() ), point_inflow, runoff,
                        std::fabs( prescribed ), std::fabs( flow_in ) } );
        return largest > 0.0 ? std::fabs( closureError() ) / largest : 0.0;
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_WATER_VOLUMES_HPP
