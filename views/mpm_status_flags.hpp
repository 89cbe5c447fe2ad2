#ifndef MPM_STATUS_FLAGS_HPP
#define MPM_STATUS_FLAGS_HPP

// Point status and node flags without Kokkos: the host-side set-up
// (src/setup/) uses them on the path of `rainslide check`, which needs no
// Kokkos (the fuzz target tests/fuzz/ builds it without).

namespace mpm
{
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

#endif // MPM_STATUS_FLAGS_HPP
