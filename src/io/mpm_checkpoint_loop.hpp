#ifndef MPM_CHECKPOINT_LOOP_HPP
#define MPM_CHECKPOINT_LOOP_HPP

#include <io/mpm_attribute_digest.hpp>
#include <io/mpm_hdf5.hpp>
#include <records/mpm_stage_state.hpp>

#include <hdf5.h>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//! Names of the links in group `loc` (at path `object`), in name order.
std::vector<std::string> linkNames( const Hdf5Ops& h5, hid_t loc,
                                    const std::string& object );

/*!
  \brief Writes the stage-loop state as group /loop of `root` in `file`:
  every field of visitStageLoopState as an attribute (the finished stages
  one group each), each also taken into `digest`.
*/
void writeLoop( const std::string& file, hid_t root, const StageLoopState& loop,
                AttributeDigest& digest );

//! Reads what writeLoop wrote into `loop`, each attribute into `digest`.
//! \throw std::runtime_error if a field is missing or of the wrong type.
void readLoop( const std::string& file, hid_t root, StageLoopState& loop,
               AttributeDigest& digest );

} // namespace Impl
} // namespace mpm

#endif // MPM_CHECKPOINT_LOOP_HPP
