#ifndef MPM_CHECKPOINT_CHECK_HPP
#define MPM_CHECKPOINT_CHECK_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>
#include <io/mpm_checkpoint_values.hpp>

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Why the values of a checkpoint (read from a damaged or edited file)
  cannot be restored into a run of config, or "" if they can: a time, step,
  wall time or snapshot count that is negative or not finite, a stage index
  past the case's stages, a removed-point count above the number of points,
  a material index outside the case's materials, a point id outside
  0..n-1, an index of a load group, pore-pressure condition or inflow
  outside the stage's lists, a point or node value outside what a run can
  reach (Impl::stateValueError: positions outside the grid, masses and
  volumes <= 0, saturations outside [S_res, S_sat], speeds and stresses
  beyond `bounds`, ...), a load whose
  count of points is not the number of points carrying it, or an inflow
  volume or length that is negative or not finite. The message names the
  dataset ("particles/m_p[0]: expected a mass > 0 kg, found 0").
*/
std::string checkpointRangeError( const Checkpoint& checkpoint,
                                  const CaseConfig& config,
                                  const Impl::StateBounds& bounds = {} );

} // namespace mpm

#endif // MPM_CHECKPOINT_CHECK_HPP
