#ifndef MPM_FOS_SEARCH_HPP
#define MPM_FOS_SEARCH_HPP

#include <functional>
#include <string>
#include <vector>

namespace mpm
{
//! How the factor of safety is searched (searchFactorOfSafety).
struct FosSearchSettings
{
    double start = 1.0;       //!< first trial factor F
    double step = 0.1;        //!< first bracketing step, doubled each trial
    double tolerance = 0.01;  //!< the answer is within +- tolerance
    double min_factor = 0.05; //!< no trial below this F
    double max_factor = 20.0; //!< no trial above this F
    int max_trials = 40;      //!< the search gives up after this many
};

//! Outcome of one trial: does the slope fail with strengths divided by F?
struct FosVerdict
{
    bool fails = false;
};

/*!
  \brief Result of a search. `found`: a stable and a failing F no more
  than 2 tolerance apart, factor = their midpoint. Otherwise `status`
  says why not ("stable_at_max_factor", "fails_at_min_factor",
  "too_many_trials") and the bracket ends not found are 0.
*/
struct FosSearchResult
{
    bool found = false;
    std::string status;
    double factor = 0.0;
    double stable = 0.0;  //!< largest F found stable (0: none)
    double failing = 0.0; //!< smallest F found failing (0: none)
    //! Every trial's F and verdict, in the order run.
    std::vector<double> trial_factors;
    std::vector<bool> trial_fails;
};

//---------------------------------------------------------------------------//
/*!
  \brief The strength-reduction factor at which `trial` changes from
  stable to failing, by bracketing then bisection. Bracketing starts at
  settings.start and moves up (stable) or down (failing) by steps that
  double, clamped to [min_factor, max_factor]; a move down that would
  cross min_factor halves the distance to it instead. Bisection then
  halves the bracket [stable, failing] until it is at most
  2 x tolerance wide. Assumes one transition: a stable F above a
  failing one is not looked for. Pure host code.
*/
FosSearchResult
searchFactorOfSafety( const FosSearchSettings& settings,
                      const std::function<FosVerdict( double )>& trial );

} // namespace mpm

#endif // MPM_FOS_SEARCH_HPP
