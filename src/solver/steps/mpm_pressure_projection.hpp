#ifndef MPM_PRESSURE_PROJECTION_HPP
#define MPM_PRESSURE_PROJECTION_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pressure_correction.hpp>
#include <mpm_pressure_newton.hpp>
#include <mpm_pressure_operator.hpp>
#include <mpm_pressure_terms.hpp>
#include <mpm_stencil_cg.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_material_params.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/steps/mpm_pressure_solve_stats.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
//! Settings of the semi-implicit pressure solve (SolverConfig).
struct PressureSolveSettings
{
    double cg_tolerance;     //!< CG: |r| <= this |b|
    int cg_max_iterations;   //!< CG iterations of one linear solve
    double newton_tolerance; //!< Newton: |R| <= this |b|
    static constexpr int max_newton_iterations = 50;
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
  start of the step), the pressure increment dp_c of each cell's free
  points that makes the corrected flow satisfy Eq. 8 over the cell at the
  new time,
    sum_p V_p dtheta_p(dp_c) / dt + (K dp)_c = sum_p V_p (source_p - r*_p),
  K = G^T mu G (+ the checkerboard penalty) the water the corrected
  velocities carry out of the cell, solved by Newton with conjugate
  gradients preconditioned by block DILU (every operation a Kokkos kernel), then
  the nodal velocities corrected by dp's forces. The points take their cell's
  dp_c in the step's point loop (PorePressurePointUpdate with
  CellPressureIncrement).
*/
template <class ExecSpace>
class PressureProjection
{
  public:
    using cell_view = Kokkos::View<double**, DeviceType<ExecSpace>>;

    PressureProjection() = default;
    explicit PressureProjection( const physics::GridGeometry& grid )
        : _terms( grid )
        , _mu_i( "pressure_mu_i", grid.nx + 1, grid.ny + 1 )
        , _system( grid.nx - 1, grid.ny - 1, grid.nx * grid.ny )
        , _work( grid.nx - 1, grid.ny - 1 )
        , _newton( "pressure_newton", grid.nx * grid.ny )
        , _k_diagonal_c( "pressure_k_diagonal_c", grid.nx, grid.ny )
        , _residual_c( "pressure_residual_c", grid.nx, grid.ny )
        , _e_c( "pressure_e_c", grid.nx, grid.ny )
    {
    }

    //! The last solve's increments dp_c per cell, Pa
    //! (WaterGridViews::dp_w_c).
    const cell_view& increments() const { return _dp_c; }

    const PressureSolveStats& stats() const { return _stats; }

    //! Each point's skeleton storage (1/Pa) joins its water storage in the
    //! solves (the fixed-stress split, QuasiStaticStep).
    void setSkeletonStorage(
        const Kokkos::View<double*, DeviceType<ExecSpace>>& skeleton_storage_p )
    {
        _terms.skeleton_storage_p = skeleton_storage_p;
    }

    /*!
      \brief Solves the step's pressure increments and corrects the nodal
      velocities of both phases (gv.v_i, dv_i, wg.v_w_i, dv_w_i). The
      storage is nonlinear (unsaturated), so the increments are iterated by
      Newton (solveNewton); the cells' terms are gathered over `lists`
      (pressurePointTerms). Throws SimulationError, naming the step
      (`step`, at simulated time `time` s), if a linear solve stops at its
      iteration cap above its tolerance.
    */
    template <class Source>
    void correct(
        const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
        const WaterParticleViews<ExecSpace>& wv, GridViews<ExecSpace>& gv,
        WaterGridViews<ExecSpace>& wg, const physics::MaterialTable& materials,
        const physics::WaterParams& water, const bool saturated,
        const double inertia_scaling, const double dt, const Source& source,
        const Kokkos::View<double***, DeviceType<ExecSpace>>& inflow_flux_i,
        const PressureSolveSettings& settings, CellPointLists<ExecSpace>& lists,
        const long step, const double time )
    {
        const physics::GridGeometry& grid = gv.geometry;
        _dp_c = wg.dp_w_c;
        pressurePointTerms( exec, pv, wv, gv, wg, water, source, lists,
                            _terms );
        pressureNodeMobility( exec, gv, wg, _terms, dt, water.viscosity,
                              inertia_scaling, inflow_flux_i, _mu_i );
        assemblePressureOperator( exec, grid, _terms, _mu_i, _system );
        keepPressureStartOnUnknowns( exec, grid, _terms, _system, _dp_c,
                                     _k_diagonal_c );
        _last = CgReport{ 0, 0.0, 0.0, 0.0, true };
        if ( _system.num_nodes > 0 )
        {
            const double residual = solveNewton(
                exec, pv, wv, materials, water, saturated, grid, dt, settings );
            if ( residual > settings.newton_tolerance )
                ++_stats.newton_unconverged;
            _stats.unbalanced_water +=
                dt * Impl::absSumOverNodes( exec, _system, _residual_c );
            _stats.max_newton_residual =
                std::max( _stats.max_newton_residual, residual );
        }
        correctNodalVelocities( exec, gv, wg, _terms, _dp_c, dt,
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
      \brief Newton's method on the cells' water (docs/formulation.md §9,
      item 4): solves A e = R and moves dp along e, with R the residual of
      Eq. 8 at the iterate (waterResidual: the stored water evaluated
      exactly, so the converged increment conserves water) and A = K +
      the tangent storage at the iterate (each cell's storage depends on
      its own dp only: A is the exact Jacobian), until |R| <=
      newton_tolerance |b|. It starts from the last step's increments if
      their residual is below |b|, else from dp = 0. A step that does not
      reduce |R| is halved (up to 6 times): a cell whose points are far in
      suction stores little per pascal, and the first solve overshoots.
    */
    double solveNewton( const ExecSpace& exec,
                        const ParticleViews<ExecSpace>& pv,
                        const WaterParticleViews<ExecSpace>& wv,
                        const physics::MaterialTable& materials,
                        const physics::WaterParams& water, const bool saturated,
                        const physics::GridGeometry& grid, const double dt,
                        const PressureSolveSettings& settings )
    {
        const auto residualAt = [&]()
        {
            return waterResidual( exec, pv, wv, materials, water, saturated,
                                  grid, dt );
        };
        const double b_norm = std::sqrt(
            Impl::dotOverNodes( exec, _system, _terms.b_c, _terms.b_c ) );
        double residual_norm = residualAt();
        if ( !( residual_norm < b_norm ) ) // from 0: no pass over the points
            residual_norm = std::sqrt( newtonResidualAtZero(
                exec, _terms.b_c, _terms.storage_c, _k_diagonal_c, dt, _dp_c,
                _residual_c, _system ) );
        int newton = 0;
        const double target = settings.newton_tolerance * b_norm;
        // The linear solve's stopping ratio beyond the first (inexact
        // Newton, Eisenstat & Walker 1996, choice 1): how far the last
        // linear model missed the new water residual, ||R| - |r_lin|| /
        // |R_old|.
        double forcing = 0.0;
        while ( residual_norm > target &&
                newton < PressureSolveSettings::max_newton_iterations )
        {
            // Solve only as far as the water residual needs: a linear step
            // solved to 0.5 target / |R| would meet the target at once; no
            // further than the linear model is right.
            const double cg_tolerance = std::max(
                { settings.cg_tolerance, 0.5 * target / residual_norm,
                  std::min( forcing, PressureSolveSettings::max_forcing ) } );
            _last =
                solveStencilCg( exec, _system, _residual_c, _e_c, _work,
                                cg_tolerance, settings.cg_max_iterations,
                                CgPreconditioner::BlockDilu, CgStart::Zero );
            ++newton;
            _stats.iterations += _last.iterations;
            _stats.max_iterations =
                std::max( _stats.max_iterations, _last.iterations );
            if ( _last.rhs_norm > 0.0 )
                _stats.max_relative_residual =
                    std::max( _stats.max_relative_residual,
                              _last.residual_norm / _last.rhs_norm );
            if ( !_last.converged )
                return 0.0; // correct() stops the run with a diagnosis
            // dp_old + step e, step = 1, 1/2, 1/4, ...: dp moves by the
            // change of the step.
            double step = 1.0, taken = 0.0;
            for ( int halving = 0;; ++halving, step *= 0.5 )
            {
                stepOverUnknowns( exec, _system, step - taken, _e_c, _dp_c );
                taken = step;
                const double norm = residualAt();
                if ( norm < residual_norm || halving == 6 )
                {
                    forcing = halving == 0
                                  ? std::abs( norm - _last.residual_norm ) /
                                        residual_norm
                                  : PressureSolveSettings::max_forcing;
                    residual_norm = norm;
                    _stats.newton_halvings += halving;
                    break;
                }
            }
        }
        _stats.newton_iterations += newton;
        _stats.max_newton_iterations =
            std::max( _stats.max_newton_iterations, newton );
        return b_norm > 0.0 ? residual_norm / b_norm : 0.0;
    }

    //! The residual R of Eq. 8 at the iterate dp (into _residual_c, A's
    //! diagonal moved to K's plus the tangent storage there) and its norm.
    double waterResidual( const ExecSpace& exec,
                          const ParticleViews<ExecSpace>& pv,
                          const WaterParticleViews<ExecSpace>& wv,
                          const physics::MaterialTable& materials,
                          const physics::WaterParams& water,
                          const bool saturated,
                          const physics::GridGeometry& grid, const double dt )
    {
        newtonStorageSums( exec, pv, wv, materials, water, saturated, grid,
                           _terms, _dp_c, dt, _newton );
        return std::sqrt( newtonResidual( exec, _newton, _terms.b_c,
                                          _k_diagonal_c, _dp_c, _residual_c,
                                          _system ) );
    }

    PressurePointTerms<ExecSpace> _terms;
    Kokkos::View<double** [2], DeviceType<ExecSpace>> _mu_i;
    NodeStencilSystem<ExecSpace> _system;
    CgWorkspace<ExecSpace> _work;
    NewtonSums<ExecSpace> _newton;
    cell_view _dp_c, _k_diagonal_c, _residual_c, _e_c;
    CgReport _last;
    PressureSolveStats _stats;
};

} // namespace mpm

#endif // MPM_PRESSURE_PROJECTION_HPP
