#ifndef MPM_POINT_CHECK_HPP
#define MPM_POINT_CHECK_HPP

#include <case/mpm_case_config.hpp>

#include <string>
#include <vector>

namespace mpm
{
//! What checking a case's material points found; messages without the
//! file name.
struct PointFindings
{
    //! Errors: the case cannot run.
    std::vector<std::string> refusals;
    //! Warnings: the case runs, but probably not as meant.
    std::vector<std::string> warnings;
};

//---------------------------------------------------------------------------//
/*!
  \brief Problems of a case that show only once its material points exist,
  found by generating them (generatePoints) as a run would. Errors: no
  point inside any body, a probe farther than one cell from every point
  (not in the soil). Warnings: a point selection of a stage (loads,
  pore_pressures, inflows) that picks no point at the points' initial
  positions (a run checks again at each stage start).
*/
PointFindings checkPoints( const CaseConfig& config );

//! The errors of checkPoints.
std::vector<std::string> pointRefusals( const CaseConfig& config );

} // namespace mpm

#endif // MPM_POINT_CHECK_HPP
