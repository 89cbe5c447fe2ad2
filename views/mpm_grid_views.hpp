#ifndef MPM_GRID_VIEWS_HPP
#define MPM_GRID_VIEWS_HPP

#include <mpm_device_type.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Allocates every View of a grid struct by its name: a cell View
  (suffix _c) has nx x ny entries, a node View (suffix _i)
  (nx + 1) x (ny + 1), a list of nodes (rank 1) one entry per node.
*/
template <class Struct>
void allocateGridViews( Struct& s, const physics::GridGeometry& grid )
{
    const int nodes_x = grid.nx + 1;
    const int nodes_y = grid.ny + 1;
    const auto allocate = [&]( const std::string& name, auto& view )
    {
        if constexpr ( std::decay_t<decltype( view )>::rank == 1 )
            allocateView( view, name, nodes_x * nodes_y );
        else if ( name.compare( name.size() - 2, 2, "_c" ) == 0 )
            allocateView( view, name, grid.nx, grid.ny );
        else
            allocateView( view, name, nodes_x, nodes_y );
    };
    Struct::forEachViewOf( allocate, s );
}

//---------------------------------------------------------------------------//
/*!
  \brief Fields on the nodes (suffix _i) and cells (suffix _c) of a
  structured grid of square 4-node cells. Nodes are indexed (i, j),
  i along x, j along y.
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct GridViews
{
    using execution_space = ExecSpace;
    using memory_space = typename ExecSpace::memory_space;
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double**, device_type, MemoryTraits>;
    using vector_view = Kokkos::View<double** [2], device_type, MemoryTraits>;
    using int_view = Kokkos::View<int**, device_type, MemoryTraits>;
    using index_view = Kokkos::View<int*, device_type, MemoryTraits>;

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

    //! Allocates every View on the nodes (on the cells: the _c Views) of
    //! `grid`.
    explicit GridViews( const physics::GridGeometry& grid )
        : geometry( grid )
    {
        allocateGridViews( *this, grid );
    }

    using unmanaged_type = GridViews<ExecSpace, Kokkos::MemoryUnmanaged>;

    //! Calls f(name, gv.view...) for every View (the checkpoint's names).
    template <class F, class... Views>
    static void forEachViewOf( F&& f, Views&... gv )
    {
        f( "m_i", gv.m_i... );
        f( "p_i", gv.p_i... );
        f( "f_i", gv.f_i... );
        f( "v_i", gv.v_i... );
        f( "dv_i", gv.dv_i... );
        f( "flags_i", gv.flags_i... );
        f( "active_i", gv.active_i... );
        f( "vol_c", gv.vol_c... );
        f( "dvol_c", gv.dvol_c... );
    }
};

//! The same Views, geometry and active-node count, unmanaged, for kernel
//! closures (see unmanaged(view)).
template <class ExecSpace>
GridViews<ExecSpace, Kokkos::MemoryUnmanaged>
unmanaged( const GridViews<ExecSpace>& gv )
{
    GridViews<ExecSpace, Kokkos::MemoryUnmanaged> u;
    assignViews( gv, u );
    u.geometry = gv.geometry;
    u.num_active = gv.num_active;
    return u;
}

} // namespace mpm

#endif // MPM_GRID_VIEWS_HPP
