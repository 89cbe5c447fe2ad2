#ifndef MPM_STATE_BOUNDS_HPP
#define MPM_STATE_BOUNDS_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint_values.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The bounds of a restored state that follow from the case's
  physics (Impl::StateBounds):
  - speeds at most solver.instability_speed_factor x the fastest initial
    wave of the case's materials (estimateRun: at saturation, the stiffest
    state), the speed at which a run stops as unstable;
  - stresses and pore pressures at most 1000 x the largest of: the
    materials' constrained moduli, the water's bulk modulus (two-phase),
    the loads' tractions and prescribed pore pressures times their time
    functions, the initial pore pressures over the grid, and the weight of
    a grid-high column of the densest material (a strain of 1000, beyond
    any run);
  - point volumes at most the grid's area x 1 m.
*/
Impl::StateBounds stateBounds( const CaseConfig& config );

} // namespace mpm

#endif // MPM_STATE_BOUNDS_HPP
