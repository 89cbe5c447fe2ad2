#ifndef MPM_WATER_VIEWS_HPP
#define MPM_WATER_VIEWS_HPP

#include <mpm_device_type.hpp>
#include <mpm_grid_views.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Pore-water fields of the material points; allocated only for
  two-phase scenes. p_w is compression positive (suction s = -p_w).
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct WaterParticleViews
{
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double*, device_type, MemoryTraits>;
    using vector_view = Kokkos::View<double* [2], device_type, MemoryTraits>;
    using int_view = Kokkos::View<int*, device_type, MemoryTraits>;

    scalar_view p_w_p;   //!< pore-water pressure, Pa
    scalar_view S_p;     //!< degree of saturation
    scalar_view dS_dp_p; //!< dS/dp_w, 1/Pa
    scalar_view k_rel_p; //!< relative permeability
    scalar_view n_p;     //!< porosity
    vector_view v_w_p;   //!< water velocity, m/s
    //! Divergence of the water velocity, 1/s (the explicit step's; the
    //! semi-implicit step does not form it).
    scalar_view div_v_w_p;
    //! Index of the prescribed pore-pressure condition, -1 if free.
    int_view p_w_condition_p;
    //! Index of the water inflow feeding the point, -1 if none.
    int_view inflow_p;
    //! The point's p_w at the start of a stage that holds it (a
    //! pore-pressure condition with hold = "initial"), Pa.
    scalar_view p_w_held_p;
    //! The point's share of its inflow relative to an even share by
    //! volume: 1, except on a polyline, where each cell takes the water of
    //! its piece of the line.
    scalar_view inflow_weight_p;

    WaterParticleViews() = default;

    //! Allocates every View with num_points entries.
    explicit WaterParticleViews( const int num_points )
    {
        allocateViews( *this, num_points );
    }

    using unmanaged_type =
        WaterParticleViews<ExecSpace, Kokkos::MemoryUnmanaged>;

    //! Calls f(name, wv.view...) for every View (the checkpoint's names).
    template <class F, class... Views>
    static void forEachViewOf( F&& f, Views&... wv )
    {
        f( "p_w_p", wv.p_w_p... );
        f( "S_p", wv.S_p... );
        f( "dS_dp_p", wv.dS_dp_p... );
        f( "k_rel_p", wv.k_rel_p... );
        f( "n_p", wv.n_p... );
        f( "v_w_p", wv.v_w_p... );
        f( "div_v_w_p", wv.div_v_w_p... );
        f( "p_w_condition_p", wv.p_w_condition_p... );
        f( "inflow_p", wv.inflow_p... );
        f( "p_w_held_p", wv.p_w_held_p... );
        f( "inflow_weight_p", wv.inflow_weight_p... );
    }

    bool allocated() const { return p_w_p.extent( 0 ) > 0; }
};

//---------------------------------------------------------------------------//
/*!
  \brief Water fields on the grid nodes (two-phase scenes). The solid
  phase and the mixture use GridViews (m_i = solid mass, p_i = solid
  momentum, f_i = mixture force).
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct WaterGridViews
{
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double**, device_type, MemoryTraits>;
    using vector_view = Kokkos::View<double** [2], device_type, MemoryTraits>;
    using int_view = Kokkos::View<int**, device_type, MemoryTraits>;

    scalar_view m_w_i; //!< water mass sum N n S rho_w V, kg
    scalar_view vol_i; //!< mixture volume sum N V, m^3
    //! Water volume fraction n S = m_w / (rho_w vol), 0 without water
    //! (set with m_w_i: the points' water divergence reads it).
    scalar_view nS_i;
    vector_view mv_w_i; //!< water momentum, kg m/s
    //! Water force per unit water volume fraction, sum N rho_w V g +
    //! sum p_w grad N V (N); times the nodal n S it is the water force.
    vector_view f_w_i;
    //! Permeability sum N k k_rel V (m^4): kv / vol is the nodal mean
    //! permeability of the drag (an average of permeabilities, not of
    //! resistances, so a dry neighbour does not block a wetting front).
    scalar_view q_i;
    vector_view v_w_i;  //!< water velocity at the end of the step, m/s
    vector_view dv_w_i; //!< water velocity increment of the step, m/s
    //! Bit mask: node_fix_x / node_fix_y tie that water velocity component
    //! to the solid's (impermeable).
    int_view flags_w_i;
    scalar_view div_w_c; //!< B-bar: volume-weighted water divergence per cell
    //! Semi-implicit: each cell's pore-pressure increment of the last
    //! step's solve, Pa (the next solve starts from it).
    scalar_view dp_w_c;

    WaterGridViews() = default;

    //! Allocates every View on the nodes (on the cells: div_w_c, dp_w_c) of
    //! `grid`.
    explicit WaterGridViews( const physics::GridGeometry& grid )
    {
        allocateGridViews( *this, grid );
    }

    using unmanaged_type = WaterGridViews<ExecSpace, Kokkos::MemoryUnmanaged>;

    //! Calls f(name, wg.view...) for every View (the checkpoint's names).
    template <class F, class... Views>
    static void forEachViewOf( F&& f, Views&... wg )
    {
        f( "m_w_i", wg.m_w_i... );
        f( "vol_i", wg.vol_i... );
        f( "nS_i", wg.nS_i... );
        f( "mv_w_i", wg.mv_w_i... );
        f( "f_w_i", wg.f_w_i... );
        f( "q_i", wg.q_i... );
        f( "v_w_i", wg.v_w_i... );
        f( "dv_w_i", wg.dv_w_i... );
        f( "flags_w_i", wg.flags_w_i... );
        f( "div_w_c", wg.div_w_c... );
        f( "dp_w_c", wg.dp_w_c... );
    }
};

} // namespace mpm

#endif // MPM_WATER_VIEWS_HPP
