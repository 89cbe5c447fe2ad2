#ifndef MPM_FOS_CRITERION_HPP
#define MPM_FOS_CRITERION_HPP

#include <case/mpm_case_config.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The failure criterion of a strength-reduction trial.

  A trial is a damped (local damping `damping`) dynamic run of
  `periods` x P under the stage's gravity, where P = 4 L / c sqrt(f) is the
  period of the slowest (drained skeleton) wave over the bodies' extent
  L (quasiStaticWindow; f the inertia scaling). The slope **fails** if
  - the largest point displacement exceeds `displacement_limit_m`
    (a collapse; the trial stops there), or
  - it still moves at the end: the largest displacement grew by more than
    `creep_limit_m` over the last quarter of the run **and** the mean
    kinetic energy of that quarter is above `energy_ratio` of the trial's
    peak (a mechanism still slowing down, not a residual drift), or
  - the run stops (a point leaves the grid, or an instability).
  Otherwise it is stable. The energy test keeps a residual creep from
  counting as a mechanism; a mechanism that has formed and is slowing down
  (a large-deformation slope just above its FS) keeps 5e-4 of its peak
  energy in the last quarter, a settled trial 1e-6 or less
  (docs/slope-study.md, "The failure criterion").
*/
struct FosCriterion
{
    double damping = 0.7;
    double periods = 10.0;
    double displacement_limit_m = 1.0;
    double creep_limit_m = 0.001;
    double energy_ratio = 1.0e-5;

    //! The thresholds (displacement and creep limits, energy ratio)
    //! multiplied by `factor`; damping and duration unchanged.
    FosCriterion scaled( double factor ) const;
};

//! The state of a trial at one time: how far and how much moved.
struct FosTrialSample
{
    double t_s = 0.0;           //!< time into the trial
    double u_max_m = 0.0;       //!< largest displacement
    double e_kin_j = 0.0;       //!< kinetic energy, J per metre
    double moved_area_m2 = 0.0; //!< initial area displaced > creep limit
};

//! What one trial measured (the criterion's numbers).
struct FosTrialRecord
{
    double factor = 0.0;
    bool fails = false;
    //! "settled", "still_moving", "displacement_limit" or "run_stopped".
    std::string reason;
    double u_max_m = 0.0;            //!< largest displacement at the end
    double u_three_quarters_m = 0.0; //!< ... at 3/4 of the duration
    double last_quarter_m = 0.0;     //!< u(T) - u(3T/4)
    //! mean E_kin over the last quarter / peak E_kin (TrialKineticEnergy)
    double ke_ratio = 0.0;
    double duration_s = 0.0; //!< simulated time run
    long steps = 0;
    double wall_s = 0.0;
    std::string error; //!< the run's error message (run_stopped)
    //! Samples at every twentieth of the duration (and at the end).
    std::vector<FosTrialSample> history;
};

/*!
  \brief Sets record.fails and record.reason from the numbers a finished
  trial recorded (u_max_m, u_three_quarters_m) by the criterion; also
  computes record.last_quarter_m. A record whose error is set fails
  ("run_stopped").
*/
void judgeTrial( const FosCriterion& criterion, FosTrialRecord& record );

/*!
  \brief The material with its strength divided by `factor`: c_peak,
  c_residual and the softening modulus H (so the residual is reached at
  the same plastic strain) and the tensile strength sigma_t0 over F;
  tan(phi) and tan(psi) over F (so psi <= phi stays psi_F <= phi_F).
  A linear elastic material is returned unchanged.
*/
MaterialConfig reducedStrength( const MaterialConfig& material, double factor );

//! One line of text stating the criterion with its numbers.
std::string describeCriterion( const FosCriterion& criterion );

//! JSON of a trial record (fos.json "trials").
nlohmann::json trialJson( const FosTrialRecord& record );

} // namespace mpm

#endif // MPM_FOS_CRITERION_HPP
