#ifndef MPM_DRY_STEP_PHASES_HPP
#define MPM_DRY_STEP_PHASES_HPP

#include <mpm_g2p.hpp>
#include <mpm_grid_update.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_p2g.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_update.hpp>
#include <mpm_scatter.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The phases of the dry MUSL step (docs/formulation.md §4) with the
  nodal sums they keep between steps. DryStep::advance runs them in order;
  the transfer tests and the benchmarks run the same phases (Duplication:
  the scatter strategy, default as the simulation's).
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
struct DryStepPhases
{
    DryNodeSums<ExecSpace, Duplication> node_sums;
    MomentumSums<ExecSpace, Duplication> momentum_sums;

    DryStepPhases() = default;

    explicit DryStepPhases( const physics::GridGeometry& grid )
        : node_sums( "p2g_dry", grid.numNodes() )
        , momentum_sums( "remap_dry", grid.numNodes() )
    {
    }

    //! 1. P2G: mass, momentum and force (gravity, loads, stress) into
    //! node_sums (scatterMassMomentumForce).
    template <class LoadView>
    void scatter( const ExecSpace& exec_space,
                  const ParticleViews<ExecSpace>& pv,
                  const physics::GridGeometry& grid, const double gravity_x,
                  const double gravity_y, const LoadView& load_force ) const
    {
        scatterMassMomentumForce( exec_space, pv, grid, gravity_x, gravity_y,
                                  load_force, node_sums );
    }

    //! 2. The grid update, which takes node_sums (gridUpdateDry).
    void updateGrid( const ExecSpace& exec_space, GridViews<ExecSpace>& gv,
                     const double dt, const double damping,
                     const double inertia_scaling ) const
    {
        gridUpdateDry( exec_space, gv, node_sums, dt, damping,
                       inertia_scaling );
    }

    //! 3-4. G2P with the remap scatter into momentum_sums, and the remap
    //! that takes them (g2pVelocityRemap, remapVelocity).
    void gatherAndRemap( const ExecSpace& exec_space,
                         const ParticleViews<ExecSpace>& pv,
                         GridViews<ExecSpace>& gv, const double dt,
                         const double flip_fraction ) const
    {
        g2pVelocityRemap( exec_space, pv, gv, dt, flip_fraction,
                          momentum_sums );
        remapVelocity( exec_space, gv, momentum_sums );
    }

    //! 6. The last point loop: gradient (B-bar with the cell averages of
    //! gv), stress, positions, diagnostics (updatePointsDry).
    PointUpdateReport updatePoints( const ExecSpace& exec_space,
                                    const ParticleViews<ExecSpace>& pv,
                                    const GridViews<ExecSpace>& gv,
                                    const physics::MaterialTable& materials,
                                    const double dt, const bool bbar,
                                    const bool remove_outside ) const
    {
        return updatePointsDry( exec_space, pv, gv, materials, dt, bbar,
                                remove_outside );
    }
};

} // namespace mpm

#endif // MPM_DRY_STEP_PHASES_HPP
