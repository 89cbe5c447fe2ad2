#ifndef MPM_RUN_RECORDS_HPP
#define MPM_RUN_RECORDS_HPP

// Plain records of a run (where it stands, stage summaries, host copies of
// the point fields), shared by the solver and the output (src/io) without
// either including the other.

#include <physics/mpm_water_volumes.hpp>

#include <string>
#include <vector>

namespace mpm
{
//! Where a run stands; passed to observers.
struct RunProgress
{
    std::string stage;
    int stage_index = 0;
    long step = 0;             //!< steps since the start of the run
    long stage_step = 0;       //!< steps since the start of the stage
    double time_s = 0.0;       //!< simulated time since the start of the run
    double stage_time_s = 0.0; //!< simulated time since the start of the stage
    double stage_duration_s = 0.0;
    double dt_s = 0.0;
    double kinetic_energy_j = 0.0;
    int active_points = 0;
};

//! Summary of one finished stage.
struct StageSummary
{
    std::string name;
    std::string type;
    long steps = 0;
    double duration_s = 0.0;
    //! Smallest and largest step the stability rule chose (steps cut short
    //! to land on a snapshot time or the stage end not counted), s.
    double dt_min_s = 0.0;
    double dt_max_s = 0.0;
    //! Quasi-static: final E_kin / max E_kin, and whether it met the tolerance.
    double ke_ratio = 0.0;
    bool converged = true;
    //! Why the stage ended: "duration", "kinetic_energy_ratio" (quasi-static
    //! converged), "static_again" (StaticStop) or "interrupted".
    std::string stop_reason = "duration";
    double max_speed_m_per_s = 0.0; //!< largest point speed in the stage
    //! Two-phase: the stage's water balance (zero in a dry scene).
    physics::WaterBalance water;
    // Static stop (recordSpeedStatistic, at the stage end): the percentile
    // p it watches (0: the stage has no static stop), its static speed,
    // the p-th percentile of the active points' speeds (nearest rank),
    // the points at or above the static speed and how many may be.
    double speed_percentile = 0.0;
    double static_speed_m_per_s = 0.0;
    double speed_at_percentile_m_per_s = 0.0;
    long points_not_below_static_speed = 0;
    long allowed_points_not_below = 0;
};

//! Host copies of every particle field, point-major.
struct HostSnapshot
{
    int num_points = 0;
    std::vector<double> x, displacement, v, sigma, eps, eps_p_bar, vol, mass;
    std::vector<int> material, id, status;
    //! Two-phase scenes only (empty otherwise).
    std::vector<double> p_w, S, n, v_w, k_rel;
};

} // namespace mpm

#endif // MPM_RUN_RECORDS_HPP
