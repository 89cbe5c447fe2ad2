#ifndef MPM_RUN_METRICS_HPP
#define MPM_RUN_METRICS_HPP

#include <case/mpm_case_config.hpp>
#include <solver/steps/mpm_auto_stats.hpp>
#include <solver/steps/mpm_pressure_solve_stats.hpp>
#include <solver/steps/mpm_skeleton_relaxation.hpp>

#include <nlohmann/json.hpp>

namespace mpm
{
//! What set a run's time step, for metrics.json's `time_step`.
struct TimeStepRecord
{
    const char* scheme;        //!< the step scheme, as the case names it
    const char* rule;          //!< how it chose the step
    const char* limiting_wave; //!< the wave whose speed limits the step
    double final_cfl_limit_s;  //!< the CFL limit at the end of the run
    double final_max_wave_speed_m_per_s;
    long steps_retaken; //!< steps given back and taken again, shorter
};

//! metrics.json's `time_step`: the rule, the scheme and its limiting wave,
//! the final CFL limit, the steps taken again.
nlohmann::json timeStepMetrics( const SolverConfig& solver,
                                const TimeStepRecord& record );

//! metrics.json's `pressure_solve`: the semi-implicit scheme's solver
//! settings and what its solves did (iterations, residuals, the water the
//! final residuals left unbalanced).
nlohmann::json pressureSolveMetrics( const SolverConfig& solver,
                                     const PressureSolveStats& solves );

//! metrics.json's `relaxation`: the quasi-static scheme's relaxation
//! settings and what its relaxations of the skeleton did.
nlohmann::json relaxationMetrics( const SolverConfig& solver,
                                  const RelaxationStats& relaxations );

//! metrics.json's `auto`: the auto scheme's settings, its switches (time,
//! scheme, reason) and each scheme's steps, wall time and step range.
nlohmann::json autoMetrics( const SolverConfig& solver,
                            const AutoStats& stats );

} // namespace mpm

#endif // MPM_RUN_METRICS_HPP
