#ifndef MPM_NODE_FORCE_RESPONSE_HPP
#define MPM_NODE_FORCE_RESPONSE_HPP

#include <mpm_status_flags.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
/*!
  \brief Step 2's drag solve at one node for forces alone (docs/formulation.md
  §9, items 2 and 3): physics::TwoPhaseNodalUpdate from rest, no damping,
  with the node's masses, drag, flags and ties. The pressure operator's
  mobility (pressureNodeMobility) and the pressure correction
  (correctNodalVelocities) both take it, so K is the correction's own
  divergence.
*/
struct NodeForceResponse
{
    double m_s;                          //!< solid mass, kg
    double m_w;                          //!< water mass, kg
    physics::NodalWater water;           //!< n S, lock and drag
    int flags;                           //!< the solid's fixities
    int flags_w;                         //!< the water's fixities
    bool flux_tied[2];                   //!< an inflow flux along x, y
    physics::TwoPhaseNodalUpdate update; //!< dt, inertia scaling

    //! The velocities along d that a mixture force f_m and a water force
    //! f_w (N) give.
    KOKKOS_INLINE_FUNCTION physics::TwoPhaseNodalUpdate::Result
    along( const int d, const double f_m, const double f_w ) const
    {
        const int bit = d == 0 ? node_fix_x : node_fix_y;
        return update( m_s, m_w, 0.0, 0.0, f_m, f_w, water.drag, flags & bit,
                       water.locked || ( flags_w & bit ) || flux_tied[d] );
    }
};

//! The NodeForceResponse of node (i, j), a node with solid mass (its n S
//! the grid update's, WaterGridViews::nS_i).
template <class Nodes, class WaterNodes, class FluxView>
KOKKOS_INLINE_FUNCTION NodeForceResponse nodeForceResponse(
    const Nodes& nodes, const WaterNodes& water_nodes, const FluxView& flux_i,
    const int i, const int j, const physics::TwoPhaseNodalUpdate& update,
    const double water_viscosity )
{
    return { nodes.m_i( i, j ),
             water_nodes.m_w_i( i, j ),
             physics::nodalWater( water_nodes.nS_i( i, j ),
                                  water_nodes.vol_i( i, j ),
                                  water_nodes.q_i( i, j ), water_viscosity ),
             nodes.flags_i( i, j ),
             water_nodes.flags_w_i( i, j ),
             { flux_i( i, j, 0 ) != 0.0, flux_i( i, j, 1 ) != 0.0 },
             update };
}

} // namespace mpm

#endif // MPM_NODE_FORCE_RESPONSE_HPP
