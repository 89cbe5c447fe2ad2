#ifndef MPM_DEVICE_TYPE_HPP
#define MPM_DEVICE_TYPE_HPP

#include <mpm_status_flags.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Device type built from an execution space. Typing every View with it keeps
//! ScatterView from inferring OpenMP for a Serial kernel (HostSpace is shared).
template <class ExecSpace>
using DeviceType = Kokkos::Device<ExecSpace, typename ExecSpace::memory_space>;

//! The unmanaged alias of a View type: same data, no reference counting.
template <class ViewType>
using UnmanagedView =
    Kokkos::View<typename ViewType::data_type, typename ViewType::array_layout,
                 typename ViewType::device_type,
                 Kokkos::MemoryTraits<Kokkos::Unmanaged>>;

/*!
  \brief The unmanaged alias of `view`, for kernel closures. A launch
  copies its closure several times and every copy of a managed View costs
  two atomic reference-count updates: with a few dozen Views per kernel
  that took a fifth of a step of 40 points. The managed View must outlive
  the kernel (true for our synchronous host kernels).
*/
template <class ViewType>
UnmanagedView<ViewType> unmanaged( const ViewType& view )
{
    return view;
}

//! True if a node's flags fix both directions of its solid.
KOKKOS_INLINE_FUNCTION bool fullyFixed( const int flags )
{
    return ( flags & node_fixed ) == node_fixed;
}

} // namespace mpm

#endif // MPM_DEVICE_TYPE_HPP
