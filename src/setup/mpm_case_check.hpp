#ifndef MPM_CASE_CHECK_HPP
#define MPM_CASE_CHECK_HPP

#include <case/mpm_case_config.hpp>
#include <setup/mpm_run_estimate.hpp>

#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
//! What refused a case that the reader accepted (CaseCheck::refused_by).
enum class CheckRefusal
{
    None,     //!< accepted
    Estimate, //!< runRefusals: cannot finish or over the budget
    Points    //!< checkPoints: no point in a body, a probe outside the soil
};

//---------------------------------------------------------------------------//
//! The outcome of checkCase for a case file the reader accepted.
struct CaseCheck
{
    CaseConfig config;
    RunEstimate estimate;
    //! One message per problem, without the file name ("" if accepted).
    std::vector<std::string> errors;
    //! Warnings of the points (a selection that picks none at the start;
    //! messages without the file name); the reader's are config.warnings.
    std::vector<std::string> point_warnings;
    CheckRefusal refused_by = CheckRefusal::None;
    bool cannot_finish = false;  //!< a time step that never ends a stage
    bool points_checked = false; //!< the points were generated and checked
    bool ok() const { return errors.empty(); }
};

//! Cases whose points x polygon vertices, or rows of points (cells[1] x
//! points per cell and direction) x polygon vertices, exceed this skip the
//! point checks (seconds of work; a run still does them).
constexpr double max_point_tests = 5.0e8;

//---------------------------------------------------------------------------//
/*!
  \brief What `rainslide check` and `run` do before any work: read the case
  (readCaseFile with the overrides), estimate the run (estimateRun), refuse
  what cannot finish or exceeds the budget (runRefusals) and, unless that
  is more work than max_point_tests, the errors that show only once the
  points exist (checkPoints, with its warnings). Needs no Kokkos; prints
  nothing.

  \throw CaseError if the file cannot be read or is not a valid case.
  \return The configuration, the estimate and the errors (empty if the case
  is accepted); the point checks are skipped if the estimate refused it.
*/
CaseCheck checkCase( const std::string& case_file,
                     const std::vector<std::string>& overrides,
                     const RunBudget& budget );

//---------------------------------------------------------------------------//
/*!
  \brief The text the CLI writes to stderr for a refused check: one line
  "file: error: message" per error and, for a refusal of the estimate, the
  estimate's summary line. "" if the case was accepted.
*/
std::string checkErrorReport( const CaseCheck& check );

} // namespace mpm

#endif // MPM_CASE_CHECK_HPP
