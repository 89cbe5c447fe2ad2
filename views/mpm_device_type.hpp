#ifndef MPM_DEVICE_TYPE_HPP
#define MPM_DEVICE_TYPE_HPP

#include <mpm_status_flags.hpp>

#include <Kokkos_Core.hpp>

#include <string>
#include <type_traits>

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
template <class ViewType,
          class = std::enable_if_t<Kokkos::is_view<ViewType>::value>>
UnmanagedView<ViewType> unmanaged( const ViewType& view )
{
    return view;
}

//! Allocates `view` as a new zeroed View labelled `name` of the given
//! extents.
template <class ViewType, class... Extents>
void allocateView( ViewType& view, const std::string& name,
                   const Extents... extents )
{
    view = ViewType( name, extents... );
}

//---------------------------------------------------------------------------//
// View structs (ParticleViews, WaterParticleViews, GridViews,
// WaterGridViews) list their Views once, in a static
// forEachViewOf(f, structs...) that calls f(name, s.view...) with the same
// View of each struct given, and name their unmanaged twin unmanaged_type.

//! Calls f(name, view) for every View of the struct s (s may be const).
template <class Struct, class F>
void forEachView( Struct& s, F&& f )
{
    std::remove_const_t<Struct>::forEachViewOf( f, s );
}

//! Allocates every View of s with the given extents, labelled by its name.
template <class Struct, class... Extents>
void allocateViews( Struct& s, const Extents... extents )
{
    Struct::forEachViewOf( [&]( const char* name, auto& view )
                           { allocateView( view, name, extents... ); },
                           s );
}

//! Makes every View of `to` the same View of `from` (the same struct
//! with other memory traits).
template <class From, class To>
void assignViews( const From& from, To& to )
{
    From::forEachViewOf( []( const char*, auto& view_from, auto& view_to )
                         { view_to = view_from; },
                         from, to );
}

//! Deep-copies every View of `from` into the same View of `to` (the same
//! struct in another execution space, e.g. its host twin).
template <class From, class To>
void copyViews( const From& from, To& to )
{
    From::forEachViewOf( []( const char*, auto& view_from, auto& view_to )
                         { Kokkos::deep_copy( view_to, view_from ); },
                         from, to );
}

/*!
  \brief The unmanaged twin of a View struct, for kernel closures (see
  unmanaged(view)): the same Views without reference counting. Plain
  members are not copied (GridViews has its own overload).
*/
template <class Struct, class = typename Struct::unmanaged_type>
typename Struct::unmanaged_type unmanaged( const Struct& s )
{
    typename Struct::unmanaged_type u;
    assignViews( s, u );
    return u;
}

//! True if a node's flags fix both directions of its solid.
KOKKOS_INLINE_FUNCTION bool fullyFixed( const int flags )
{
    return ( flags & node_fixed ) == node_fixed;
}

} // namespace mpm

#endif // MPM_DEVICE_TYPE_HPP
