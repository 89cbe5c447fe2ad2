#ifndef MPM_FOS_CRITERION_HPP
#define MPM_FOS_CRITERION_HPP

#include <io/mpm_case_config.hpp>

#include <nlohmann/json.hpp>

#include <string>

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
    (the trial stops there), or
  - it is still growing at the end: u(T) > `moving_floor_m` and
    (u(T) - u(3T/4)) / u(T) > `growth_ratio`, or
  - the run stops (a point leaves the grid, or an instability).
  Otherwise it is stable: the displacement came to rest.
*/
struct FosCriterion
{
    double damping = 0.7;
    double periods = 10.0;
    double growth_ratio = 0.01;
    double displacement_limit_m = 1.0;
    double moving_floor_m = 0.001;

    //! The thresholds (growth ratio, displacement limit, moving floor)
    //! multiplied by `factor`; damping and duration unchanged.
    FosCriterion scaled( double factor ) const;
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
    double growth_ratio = 0.0;       //!< (u(T) - u(3T/4)) / u(T)
    double ke_ratio = 0.0;           //!< E_kin(end) / max E_kin
    double duration_s = 0.0;         //!< simulated time run
    long steps = 0;
    double wall_s = 0.0;
    std::string error; //!< the run's error message (run_stopped)
};

/*!
  \brief Sets record.fails and record.reason from the numbers a finished
  trial recorded (u_max_m, u_three_quarters_m) by the criterion; also
  computes record.growth_ratio. A record whose error is set fails
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
