#ifndef MPM_POINT_CHECK_HPP
#define MPM_POINT_CHECK_HPP

#include <io/mpm_case_config.hpp>

#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Errors of a case that show only once its material points exist,
  found by generating them (generatePoints) as a run would: no point inside
  any body, a probe farther than one cell from every point (not in the
  soil). One message per problem, without the file name.
*/
std::vector<std::string> pointRefusals( const CaseConfig& config );

} // namespace mpm

#endif // MPM_POINT_CHECK_HPP
