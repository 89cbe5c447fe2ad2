#ifndef MPM_CHECKPOINT_CHECK_HPP
#define MPM_CHECKPOINT_CHECK_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Why the values of a checkpoint (read from a damaged or forged file)
  cannot be restored into a run of config, or "" if they can: a time, step,
  wall time or snapshot count that is negative or not finite, a stage index
  past the case's stages, a removed-point count above the number of points,
  a material index outside the case's materials, a point id outside
  0..n-1, or a point value that is not finite (NaN or infinite positions,
  stresses, ...: a restored NaN crashed G2P).
*/
std::string checkpointRangeError( const Checkpoint& checkpoint,
                                  const CaseConfig& config );

} // namespace mpm

#endif // MPM_CHECKPOINT_CHECK_HPP
