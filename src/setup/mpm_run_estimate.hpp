#ifndef MPM_RUN_ESTIMATE_HPP
#define MPM_RUN_ESTIMATE_HPP

#include <case/mpm_case_config.hpp>

#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief What a run may use before `check` or `run` accepts a case; 0
  means no limit. Set on the command line (--max-steps, --max-memory-gb,
  --max-output-gb, --max-snapshots).
*/
struct RunBudget
{
    double max_steps = 2.0e7;
    double max_memory_gb = 16.0;
    double max_output_gb = 20.0;
    double max_snapshots = 20000.0;
};

//---------------------------------------------------------------------------//
//! Estimate of one stage.
struct StageEstimate
{
    std::string name;
    double dt_s = 0.0;      //!< initial time step (CFL or solver.dt_s), s
    double steps = 0.0;     //!< upper bound (a quasi-static stage may stop)
    double snapshots = 0.0; //!< snapshots written by the stage
};

//---------------------------------------------------------------------------//
//! Estimate of a whole run from the case alone (no points generated).
struct RunEstimate
{
    double points = 0.0; //!< sum of body areas x points per cell area
    double cells = 0.0;
    double nodes = 0.0;
    double max_wave_speed_m_per_s = 0.0; //!< fastest initial wave
    std::string fastest_material;        //!< its material's name
    std::vector<StageEstimate> stages;
    double steps = 0.0;
    double snapshots = 0.0;
    double memory_bytes = 0.0;
    double probe_rows = 0.0; //!< rows of probes.csv: probes x samples
    //! particles.h5 (snapshots), probes.csv and the checkpoint
    double output_bytes = 0.0;
};

//---------------------------------------------------------------------------//
/*!
  \brief Estimate the points, cells, time step, steps, snapshots, memory and
  output of a run. The time step is the initial CFL step
  courant_number x cell_size x sqrt(inertia_scaling) / c of the fastest
  initial P-wave c over every stage's materials (points at rest; two-phase
  at saturation, the stiffest state), or solver.dt_s if set. Memory and
  output use per-point and per-node sizes of the current data layout; the
  output counts a probes.csv row per probe every probes.interval_s (at most
  one a step) and at each stage start.
*/
RunEstimate estimateRun( const CaseConfig& config );

//---------------------------------------------------------------------------//
/*!
  \brief Why a run of this case cannot finish or would exceed the budget:
  one message per problem ("" if none). A run that cannot finish (a time
  step of 0, or too small to advance the time) is refused whatever the
  budget and sets cannot_finish.
*/
std::vector<std::string> runRefusals( const CaseConfig& config,
                                      const RunEstimate& estimate,
                                      const RunBudget& budget,
                                      bool& cannot_finish );

//---------------------------------------------------------------------------//
//! \brief One line: "estimate: N points, M cells, dt ..., S steps, ...".
std::string estimateSummary( const RunEstimate& estimate );

} // namespace mpm

#endif // MPM_RUN_ESTIMATE_HPP
