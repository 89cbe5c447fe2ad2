#ifndef MPM_PRESSURE_SOLVE_STATS_HPP
#define MPM_PRESSURE_SOLVE_STATS_HPP

namespace mpm
{
//! What the semi-implicit scheme's pressure solves did over a run.
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
};

} // namespace mpm

#endif // MPM_PRESSURE_SOLVE_STATS_HPP
