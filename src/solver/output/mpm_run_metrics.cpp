#include <solver/output/mpm_run_metrics.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
nlohmann::json timeStepMetrics( const SolverConfig& solver,
                                const TimeStepRecord& record )
{
    return {
        { "rule", record.rule },
        { "scheme", record.scheme },
        { "limiting_wave", record.limiting_wave },
        { "courant_number", solver.courant_number },
        { "inertia_scaling", solver.inertia_scaling },
        { "final_cfl_limit_s", record.final_cfl_limit_s },
        { "final_max_wave_speed_m_per_s", record.final_max_wave_speed_m_per_s },
        { "steps_retaken", record.steps_retaken } };
}

//---------------------------------------------------------------------------//
nlohmann::json pressureSolveMetrics( const SolverConfig& solver,
                                     const PressureSolveStats& solves )
{
    const auto mean = [&]( const long total ) {
        return solves.solves > 0 ? double( total ) / double( solves.solves )
                                 : 0.0;
    };
    return { { "method", "Newton on each cell's pressure increment, each "
                         "linear solve by conjugate gradients preconditioned "
                         "by block DILU (picard_*: the Newton iteration)" },
             { "tolerance", solver.pressure_tolerance },
             { "max_iterations_allowed",
               static_cast<int>( solver.pressure_max_iterations ) },
             { "solves", solves.solves },
             { "iterations_total", solves.iterations },
             { "iterations_mean", mean( solves.iterations ) },
             { "iterations_max", solves.max_iterations },
             { "max_unknowns", solves.max_unknowns },
             { "worst_relative_residual", solves.max_relative_residual },
             { "picard_tolerance", solver.pressure_picard_tolerance },
             { "picard_solves_total", solves.newton_iterations },
             { "picard_solves_mean", mean( solves.newton_iterations ) },
             { "picard_solves_max", solves.max_newton_iterations },
             { "picard_halvings_total", solves.newton_halvings },
             { "picard_unconverged_steps", solves.newton_unconverged },
             { "picard_worst_water_residual", solves.max_newton_residual },
             { "picard_unbalanced_water_m3_per_m", solves.unbalanced_water } };
}

//---------------------------------------------------------------------------//
nlohmann::json relaxationMetrics( const SolverConfig& solver,
                                  const RelaxationStats& relaxations )
{
    return { { "method", "damped two-phase steps at the skeleton's CFL "
                         "limit, each point's p_w held, until the fastest "
                         "point is slower than the rest speed" },
             { "rest_speed_m_per_s", solver.relaxation_speed_m_per_s },
             { "damping", solver.relaxation_damping },
             { "max_steps_allowed",
               static_cast<long>( solver.relaxation_max_steps ) },
             { "relaxations", relaxations.relaxations },
             { "steps_total", relaxations.steps },
             { "steps_mean", relaxations.relaxations > 0
                                 ? double( relaxations.steps ) /
                                       double( relaxations.relaxations )
                                 : 0.0 },
             { "steps_max", relaxations.max_steps } };
}

//---------------------------------------------------------------------------//
nlohmann::json autoMetrics( const SolverConfig& solver, const AutoStats& stats )
{
    const auto steps = []( const SchemeSteps& taken, const char* limit )
    {
        return nlohmann::json{
            { "steps", taken.steps },
            { "wall_s", taken.wall_s },
            { "min_step_s", taken.steps > 0 ? taken.min_step_s : 0.0 },
            { "max_step_s", taken.max_step_s },
            { "step_set_by", limit } };
    };
    nlohmann::json switches = nlohmann::json::array();
    for ( const SchemeSwitch& change : stats.switches )
        switches.push_back( { { "time_s", change.time_s },
                              { "to", change.to },
                              { "reason", change.reason } } );
    return { { "rest_speed_m_per_s", solver.auto_rest_speed_m_per_s },
             { "rest_window_s", solver.auto_rest_window_s },
             { "switches", switches },
             { "quasi_static", steps( stats.quasi_static,
                                      "the flow's saturation change "
                                      "(solver.seepage_saturation_change)" ) },
             { "semi_implicit",
               steps( stats.dynamic, "courant_number x the skeleton's CFL "
                                     "limit" ) } };
}

} // namespace mpm
