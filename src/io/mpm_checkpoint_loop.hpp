#ifndef MPM_CHECKPOINT_LOOP_HPP
#define MPM_CHECKPOINT_LOOP_HPP

#include <io/mpm_attribute_digest.hpp>
#include <io/mpm_hdf5.hpp>
#include <records/mpm_stage_state.hpp>

#include <hdf5.h>

#include <string>

namespace mpm
{
namespace Impl
{
/*!
  \brief Writes the stage-loop state as group /loop of `root` in `file`:
  one string attribute "json", the state's JSON text (stageLoopStateJson,
  src/io/mpm_stage_state_json.hpp), also taken into `digest`.
*/
void writeLoop( const std::string& file, hid_t root, const StageLoopState& loop,
                AttributeDigest& digest );

//! Reads what writeLoop wrote into `loop`, the attribute into `digest`.
//! \throw std::runtime_error if it is missing, not JSON, or a field is
//! missing, unknown, of the wrong type or out of range.
void readLoop( const std::string& file, hid_t root, StageLoopState& loop,
               AttributeDigest& digest );

} // namespace Impl
} // namespace mpm

#endif // MPM_CHECKPOINT_LOOP_HPP
