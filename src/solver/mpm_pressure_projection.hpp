#ifndef MPM_PRESSURE_PROJECTION_HPP
#define MPM_PRESSURE_PROJECTION_HPP

#include <io/mpm_case_config.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pressure_assembly.hpp>
#include <mpm_pressure_correction.hpp>
#include <mpm_pressure_picard.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <solver/mpm_simulation_error.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
//! What the semi-implicit scheme's pressure solves did over a run.
struct PressureSolveStats
{
    long solves = 0;                    //!< steps with a pressure solve
    long iterations = 0;                //!< CG iterations, all solves
    int max_iterations = 0;             //!< most iterations of one solve
    double max_relative_residual = 0.0; //!< worst |r| / |b| at the end
    long max_unknowns = 0;              //!< most unknown nodes of one solve
    long picard_iterations = 0;         //!< linear solves, all steps
    int max_picard_iterations = 0;      //!< most linear solves of one step
    long picard_unconverged = 0;        //!< steps that ended above it
    long picard_halvings = 0;           //!< line-search halvings, all steps
    //! Worst water residual |R| / |b| a step ended with.
    double max_picard_residual = 0.0;
    //! Water the steps' final residuals left unbalanced, sum of |R_I| dt
    //! over the unknowns and steps, m^3 per m of thickness.
    double unbalanced_water = 0.0;
};

//! Settings of the semi-implicit pressure solve (SolverConfig).
struct PressureSolveSettings
{
    double cg_tolerance;     //!< CG: |r| <= this |b|
    int cg_max_iterations;   //!< CG iterations of one linear solve
    double picard_tolerance; //!< Picard: |R| <= this |b|
    static constexpr int max_picard_iterations = 50;
    //! Loosest stopping ratio of a linear solve after the first (the
    //! inexact Newton forcing term's cap).
    static constexpr double max_forcing = 0.1;
};

//! The pressure solve's settings of a case's [solver].
inline PressureSolveSettings pressureSolveSettings( const SolverConfig& s )
{
    return { s.pressure_tolerance,
             static_cast<int>( s.pressure_max_iterations ),
             s.pressure_picard_tolerance };
}

//---------------------------------------------------------------------------//
/*!
  \brief The pressure correction of the semi-implicit two-phase step
  (docs/formulation.md §9): after step 2 (the predictor, with p_w at the
  start of the step), the nodal pressure increment dp that makes the
  corrected flow satisfy Eq. 8 at the new time,
    (sum_p N_I C_p V_p / dt) dp_I + dt sum_J (sum_p V_p M_p grad N_I .
      grad N_J) dp_J = sum_p N_I V_p (source_p - r*_p),
  solved by Jacobi-preconditioned conjugate gradients (every operation a
  Kokkos kernel), then the nodal velocities corrected by dp's forces. The
  points take dp_p = sum_I N_I dp_I in the step's point loop
  (PorePressurePointUpdate, `projected`).
*/
template <class ExecSpace>
class PressureProjection
{
  public:
    using node_view = Kokkos::View<double**, DeviceType<ExecSpace>>;

    PressureProjection() = default;
    PressureProjection( const physics::GridGeometry& grid,
                        const int num_points )
        : _terms( grid, num_points )
        , _stencil_sums( grid )
        , _system( grid.nx, grid.ny, grid.numNodes() )
        , _work( grid.nx, grid.ny )
        , _b_i( "pressure_b_i", grid.nx + 1, grid.ny + 1 )
        , _forces( "pressure_forces", grid.numNodes() )
        , _storage_i( "pressure_storage_i", grid.nx + 1, grid.ny + 1 )
        , _a_dp_i( "pressure_a_dp_i", grid.nx + 1, grid.ny + 1 )
        , _residual_i( "pressure_residual_i", grid.nx + 1, grid.ny + 1 )
        , _e_i( "pressure_e_i", grid.nx + 1, grid.ny + 1 )
        , _dp_old_i( "pressure_dp_old_i", grid.nx + 1, grid.ny + 1 )
        , _picard( "pressure_picard", grid.numNodes() )
    {
    }

    //! The last solve's nodal increments dp_i, Pa (WaterGridViews::dp_w_i).
    const node_view& increments() const { return _dp_i; }

    const PressureSolveStats& stats() const { return _stats; }

    /*!
      \brief Solves the step's pressure increment and corrects the nodal
      velocities of both phases (gv.v_i, dv_i, wg.v_w_i, dv_w_i). The
      storage is nonlinear (unsaturated), so the increment is iterated by
      modified Picard (solvePicard). Throws SimulationError, naming the
      step (`step`, at simulated time `time` s), if a linear solve stops
      at its iteration cap above its tolerance.
    */
    template <class Source>
    void correct(
        const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
        const WaterParticleViews<ExecSpace>& wv, GridViews<ExecSpace>& gv,
        WaterGridViews<ExecSpace>& wg, const physics::MaterialTable& materials,
        const physics::WaterParams& water, const bool saturated,
        const double inertia_scaling, const double dt, const Source& source,
        const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i,
        const PressureSolveSettings& settings, const long step,
        const double time )
    {
        _dp_i = wg.dp_w_i;
        pressurePointTerms( exec, pv, wv, gv, wg, materials, water,
                            inertia_scaling, dt, source, _terms );
        assemblePressureStencil( exec, pv, _terms.mobility_p, _terms.storage_p,
                                 gv.geometry, dt, _stencil_sums, _system );
        listPressureUnknowns( exec, gv, wg, _terms, _b_i, _dp_i, _storage_i,
                              _system );
        if ( _system.num_nodes > 0 )
        {
            const double residual = solvePicard(
                exec, pv, wv, gv, materials, water, saturated, dt, settings );
            if ( residual > settings.picard_tolerance )
                ++_stats.picard_unconverged;
            _stats.unbalanced_water +=
                dt * Impl::absSumOverNodes( exec, _system, _residual_i );
            _stats.max_picard_residual =
                std::max( _stats.max_picard_residual, residual );
        }
        else
            _last = CgReport{ 0, 0.0, 0.0, 0.0, true };
        scatterPressureForces( exec, pv, wv, gv.geometry, _dp_i, _forces );
        correctNodalVelocities( exec, gv, wg, _forces, dt, water.density,
                                water.viscosity, inertia_scaling,
                                inflow_flux_i );
        ++_stats.solves;
        _stats.max_unknowns =
            std::max( _stats.max_unknowns, long( _system.num_nodes ) );
        if ( _last.converged )
            return;
        std::ostringstream what;
        what << "the pressure solve of step " << step << " (t = " << time
             << " s, dt = " << dt << " s) did not converge: residual "
             << _last.residual_norm << " m^3/s against " << _last.tolerance
             << " x " << _last.rhs_norm << " after " << _last.iterations
             << " iterations (solver.pressure_max_iterations); a smaller "
                "courant_number or dt_s, or a larger pressure_max_iterations, "
                "may help";
        throw SimulationError( what.str() );
    }

  private:
    /*!
      \brief Modified Picard (docs/formulation.md §9, item 4): from dp = 0,
      solves A e = R and moves dp along e, with R the residual of Eq. 8 at
      the iterate (waterResidual: the stored water evaluated exactly, so
      the converged increment conserves water) and A's storage at the
      iterate, until |R| <= picard_tolerance |b|. It starts from the last
      step's increment if its residual is below |b|, else from dp = 0. A step
      that does not reduce |R| is halved (up to 6 times): from a saturated
      point, whose storage is only n S / K_w, the first solve overshoots
      far into suction.
    */
    double solvePicard( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        GridViews<ExecSpace>& gv,
                        const physics::MaterialTable& materials,
                        const physics::WaterParams& water, const bool saturated,
                        const double dt, const PressureSolveSettings& settings )
    {
        const double b_norm =
            std::sqrt( Impl::dotOverNodes( exec, _system, _b_i, _b_i ) );
        double residual_norm =
            waterResidual( exec, pv, wv, gv, materials, water, saturated, dt );
        if ( !( residual_norm < b_norm ) )
        {
            Kokkos::deep_copy( exec, _dp_i, 0.0 );
            Kokkos::deep_copy( exec, _residual_i, _b_i );
            residual_norm = b_norm;
        }
        int picard = 0;
        const double target = settings.picard_tolerance * b_norm;
        // The linear solve's stopping ratio beyond the first (inexact
        // Newton, Eisenstat & Walker 1996, choice 1): how far the last
        // linear model missed the new water residual, ||R| - |r_lin|| /
        // |R_old|.
        double forcing = 0.0;
        while ( residual_norm > target &&
                picard < PressureSolveSettings::max_picard_iterations )
        {
            // Solve only as far as the water residual needs: a linear step
            // solved to 0.5 target / |R| would meet the target at once; no
            // further than the linear model is right.
            const double cg_tolerance = std::max(
                { settings.cg_tolerance, 0.5 * target / residual_norm,
                  std::min( forcing, PressureSolveSettings::max_forcing ) } );
            Kokkos::deep_copy( exec, _e_i, 0.0 );
            _last = solveJacobiCg( exec, _system, _residual_i, _e_i, _work,
                                   cg_tolerance, settings.cg_max_iterations );
            ++picard;
            _stats.iterations += _last.iterations;
            _stats.max_iterations =
                std::max( _stats.max_iterations, _last.iterations );
            if ( _last.rhs_norm > 0.0 )
                _stats.max_relative_residual =
                    std::max( _stats.max_relative_residual,
                              _last.residual_norm / _last.rhs_norm );
            if ( !_last.converged )
                return 0.0; // correct() stops the run with a diagnosis
            Kokkos::deep_copy( exec, _dp_old_i, _dp_i );
            double step = 1.0;
            for ( int halving = 0;; ++halving, step *= 0.5 )
            {
                stepOverUnknowns( exec, _system, _dp_old_i, step, _e_i, _dp_i );
                const double norm = waterResidual( exec, pv, wv, gv, materials,
                                                   water, saturated, dt );
                if ( norm < residual_norm || halving == 6 )
                {
                    forcing = halving == 0
                                  ? std::abs( norm - _last.residual_norm ) /
                                        residual_norm
                                  : PressureSolveSettings::max_forcing;
                    residual_norm = norm;
                    _stats.picard_halvings += halving;
                    break;
                }
            }
        }
        _stats.picard_iterations += picard;
        _stats.max_picard_iterations =
            std::max( _stats.max_picard_iterations, picard );
        return b_norm > 0.0 ? residual_norm / b_norm : 0.0;
    }

    //! The residual R of Eq. 8 at the iterate dp (into _residual_i, A's
    //! storage moved to the iterate) and its norm.
    double waterResidual( const ExecSpace& exec,
                          const ParticleViews<ExecSpace>& pv,
                          const WaterParticleViews<ExecSpace>& wv,
                          GridViews<ExecSpace>& gv,
                          const physics::MaterialTable& materials,
                          const physics::WaterParams& water,
                          const bool saturated, const double dt )
    {
        picardStorageSums( exec, pv, wv, materials, water, saturated,
                           gv.geometry, _dp_i, dt, _picard );
        Impl::applyStencil( exec, _system, _dp_i, _a_dp_i );
        picardResidual( exec, gv, _terms.unknown_i, _picard, _b_i, _dp_i,
                        _a_dp_i, _storage_i, _residual_i, _system );
        return std::sqrt(
            Impl::dotOverNodes( exec, _system, _residual_i, _residual_i ) );
    }

    PressurePointTerms<ExecSpace> _terms;
    PressureStencilSums<ExecSpace> _stencil_sums;
    NodeStencilSystem<ExecSpace> _system;
    CgWorkspace<ExecSpace> _work;
    node_view _b_i, _dp_i;
    PressureForceSums<ExecSpace> _forces;
    node_view _storage_i, _a_dp_i, _residual_i, _e_i, _dp_old_i;
    PicardSums<ExecSpace> _picard;
    CgReport _last;
    PressureSolveStats _stats;
};

} // namespace mpm

#endif // MPM_PRESSURE_PROJECTION_HPP
