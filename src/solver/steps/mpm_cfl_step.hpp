#ifndef MPM_CFL_STEP_HPP
#define MPM_CFL_STEP_HPP

#include <case/mpm_case_config.hpp>
#include <mpm_timestep.hpp>
#include <solver/mpm_simulation_error.hpp>
#include <solver/steps/mpm_skeleton_relaxation.hpp>

#include <sstream>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Time step of a stage: the fixed dt_s of the case, refused if it
  exceeds the CFL limit, or Courant number times the CFL limit.
*/
inline double chooseTimeStep( const SolverConfig& solver,
                              const WaveSpeedLimit& limit )
{
    if ( solver.dt_s <= 0.0 )
        return solver.courant_number * limit.dt_limit;
    if ( solver.dt_s > limit.dt_limit )
    {
        std::ostringstream msg;
        msg << "solver.dt_s = " << solver.dt_s << " s exceeds the stable limit "
            << limit.dt_limit
            << " s (cell size / (P-wave speed + point speed), largest P-wave "
               "speed "
            << limit.max_wave_speed << " m/s); use dt_s <= " << limit.dt_limit
            << " s or dt_s = 0 for the automatic step";
        throw SimulationError( msg.str() );
    }
    return solver.dt_s;
}

//---------------------------------------------------------------------------//
//! What the schemes whose step a wave limits share (StepScheme): their
//! steps do not end at rest (a quasi-static stage damps them to rest), they
//! take courant_number x their CFL limit, or solver.dt_s checked against it
//! (chooseTimeStep), and keep no water in transit.
struct CflStepRule
{
    static constexpr bool ends_at_rest = false;
    static constexpr const char* automatic_step =
        "automatic: courant_number x cell / (fastest wave speed + point "
        "speed)";
    static constexpr const char* fixed_step =
        "fixed dt_s, checked against the CFL limit";

    //! The next step at the CFL limit `limit` of the state now.
    template <class State>
    double nextStep( const State& s, const WaveSpeedLimit& limit ) const
    {
        return chooseTimeStep( s.solver, limit );
    }

    //! A stage's start changes nothing; no step is ever given back.
    void startStage( const SolverConfig& ) {}
    bool stepGivenBack() const { return false; }
    long stepsRetaken() const { return 0; }

    //! No water in transit, no relaxation.
    double waterInTransit() const { return 0.0; }
    const RelaxationStats* relaxationStats() const { return nullptr; }
};

} // namespace mpm

#endif // MPM_CFL_STEP_HPP
