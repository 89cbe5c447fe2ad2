#ifndef MPM_DEVICE_TYPE_HPP
#define MPM_DEVICE_TYPE_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Device type built from an execution space. Typing every View with it keeps
//! ScatterView from inferring OpenMP for a Serial kernel (HostSpace is shared).
template <class ExecSpace>
using DeviceType = Kokkos::Device<ExecSpace, typename ExecSpace::memory_space>;

//! Status of a material point.
enum PointStatus : int
{
    point_removed = 0, //!< left the grid and was removed (not simulated)
    point_active = 1
};

//! Boundary flags of a grid node (bit mask).
enum NodeFlag : int
{
    node_free = 0,
    node_fix_x = 1,
    node_fix_y = 2,
    node_fixed = 3
};

} // namespace mpm

#endif // MPM_DEVICE_TYPE_HPP
