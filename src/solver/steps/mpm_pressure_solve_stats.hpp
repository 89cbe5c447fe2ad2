#ifndef MPM_PRESSURE_SOLVE_STATS_HPP
#define MPM_PRESSURE_SOLVE_STATS_HPP

#include <algorithm>

namespace mpm
{
//! What a scheme's pressure solves did over a run.
struct PressureSolveStats
{
    long solves = 0;                    //!< steps with a pressure solve
    long iterations = 0;                //!< CG iterations, all solves
    int max_iterations = 0;             //!< most iterations of one solve
    double max_relative_residual = 0.0; //!< worst |r| / |b| at the end
    long max_unknowns = 0;              //!< most unknown cells of one solve
    long newton_iterations = 0;         //!< linear solves, all steps
    int max_newton_iterations = 0;      //!< most linear solves of one step
    long newton_unconverged = 0;        //!< steps that ended above it
    long newton_halvings = 0;           //!< line-search halvings, all steps
    //! Worst water residual |R| / |b| a step ended with.
    double max_newton_residual = 0.0;
    //! Water the steps' final residuals left unbalanced, sum of |R_I| dt
    //! over the unknowns and steps, m^3 per m of thickness.
    double unbalanced_water = 0.0;

    //! The solves of `other` added to these (the auto scheme's two kinds).
    void add( const PressureSolveStats& other )
    {
        solves += other.solves;
        iterations += other.iterations;
        max_iterations = std::max( max_iterations, other.max_iterations );
        max_relative_residual =
            std::max( max_relative_residual, other.max_relative_residual );
        max_unknowns = std::max( max_unknowns, other.max_unknowns );
        newton_iterations += other.newton_iterations;
        max_newton_iterations =
            std::max( max_newton_iterations, other.max_newton_iterations );
        newton_unconverged += other.newton_unconverged;
        newton_halvings += other.newton_halvings;
        max_newton_residual =
            std::max( max_newton_residual, other.max_newton_residual );
        unbalanced_water += other.unbalanced_water;
    }
};

} // namespace mpm

#endif // MPM_PRESSURE_SOLVE_STATS_HPP
