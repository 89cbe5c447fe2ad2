#ifndef MPM_BBAR_CELL_AVERAGES_HPP
#define MPM_BBAR_CELL_AVERAGES_HPP

#include <mpm_velocity_gradient.hpp>
#include <solver/mpm_simulation_state.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Step 5 with B-bar (Hughes 1980), in every scheme: each point's
  velocity gradient (two-phase: and water divergence), summed per cell
  (velocityGradientCellSums), and the cell averages the point loop takes
  (takeCellSums). The cell sums are allocated at the first use.
*/
template <class ExecSpace>
class BbarCellAverages
{
  public:
    void operator()( const ExecSpace& exec, SimulationState<ExecSpace>& state )
    {
        if ( !_sums.allocated() )
            _sums = CellSums<ExecSpace>(
                "bbar_cells", state.grid.geometry.nx * state.grid.geometry.ny );
        velocityGradientCellSums( exec, state.particles, state.water_particles,
                                  state.grid, state.water_grid, _sums );
        takeCellSums( exec, state.grid, state.water_grid, _sums );
    }

  private:
    CellSums<ExecSpace> _sums;
};

} // namespace mpm

#endif // MPM_BBAR_CELL_AVERAGES_HPP
