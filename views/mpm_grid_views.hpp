#ifndef MPM_GRID_VIEWS_HPP
#define MPM_GRID_VIEWS_HPP

#include <mpm_device_type.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Fields on the nodes (suffix _i) and cells (suffix _c) of a
  structured grid of square 4-node cells. Nodes are indexed (i, j),
  i along x, j along y.
*/
template <class ExecSpace>
struct GridViews
{
    using execution_space = ExecSpace;
    using memory_space = typename ExecSpace::memory_space;
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double**, device_type>;
    using vector_view = Kokkos::View<double** [2], device_type>;
    using int_view = Kokkos::View<int**, device_type>;
    using index_view = Kokkos::View<int*, device_type>;

    physics::GridGeometry geometry;
    scalar_view m_i;     //!< nodal mass, kg
    vector_view p_i;     //!< nodal momentum, kg m/s
    vector_view f_i;     //!< nodal force (internal + external), N
    vector_view v_i;     //!< nodal velocity at the end of the step, m/s
    vector_view dv_i;    //!< nodal velocity increment of the step, m/s
    int_view flags_i;    //!< NodeFlag bit mask
    index_view active_i; //!< flat indices i * ny1 + j of nodes with mass
    int num_active = 0;  //!< number of valid entries in active_i
    scalar_view vol_c;   //!< B-bar: point volume summed per cell, m^3
    scalar_view dvol_c;  //!< B-bar: volume-weighted volumetric rate, m^3/s

    GridViews() = default;

    explicit GridViews( const physics::GridGeometry& grid )
        : geometry( grid )
        , m_i( "m_i", grid.nx + 1, grid.ny + 1 )
        , p_i( "p_i", grid.nx + 1, grid.ny + 1 )
        , f_i( "f_i", grid.nx + 1, grid.ny + 1 )
        , v_i( "v_i", grid.nx + 1, grid.ny + 1 )
        , dv_i( "dv_i", grid.nx + 1, grid.ny + 1 )
        , flags_i( "flags_i", grid.nx + 1, grid.ny + 1 )
        , active_i( "active_i", ( grid.nx + 1 ) * ( grid.ny + 1 ) )
        , vol_c( "vol_c", grid.nx, grid.ny )
        , dvol_c( "dvol_c", grid.nx, grid.ny )
    {
    }
};

} // namespace mpm

#endif // MPM_GRID_VIEWS_HPP
