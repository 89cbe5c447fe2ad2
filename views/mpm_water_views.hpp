#ifndef MPM_WATER_VIEWS_HPP
#define MPM_WATER_VIEWS_HPP

#include <mpm_device_type.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Pore-water fields of the material points; allocated only for
  two-phase scenes. p_w is compression positive (suction s = -p_w).
*/
template <class ExecSpace>
struct WaterParticleViews
{
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double*, device_type>;
    using vector_view = Kokkos::View<double* [2], device_type>;
    using int_view = Kokkos::View<int*, device_type>;

    scalar_view p_w_p;     //!< pore-water pressure, Pa
    scalar_view S_p;       //!< degree of saturation
    scalar_view dS_dp_p;   //!< dS/dp_w, 1/Pa
    scalar_view k_rel_p;   //!< relative permeability
    scalar_view n_p;       //!< porosity
    vector_view v_w_p;     //!< water velocity, m/s
    scalar_view div_v_w_p; //!< divergence of the water velocity, 1/s
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

    explicit WaterParticleViews( const int num_points )
        : p_w_p( "p_w_p", num_points )
        , S_p( "S_p", num_points )
        , dS_dp_p( "dS_dp_p", num_points )
        , k_rel_p( "k_rel_p", num_points )
        , n_p( "n_p", num_points )
        , v_w_p( "v_w_p", num_points )
        , div_v_w_p( "div_v_w_p", num_points )
        , p_w_condition_p( "p_w_condition_p", num_points )
        , inflow_p( "inflow_p", num_points )
        , p_w_held_p( "p_w_held_p", num_points )
        , inflow_weight_p( "inflow_weight_p", num_points )
    {
    }

    bool allocated() const { return p_w_p.extent( 0 ) > 0; }
};

//---------------------------------------------------------------------------//
/*!
  \brief Water fields on the grid nodes (two-phase scenes). The solid
  phase and the mixture use GridViews (m_i = solid mass, p_i = solid
  momentum, f_i = mixture force).
*/
template <class ExecSpace>
struct WaterGridViews
{
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double**, device_type>;
    using vector_view = Kokkos::View<double** [2], device_type>;
    using int_view = Kokkos::View<int**, device_type>;

    scalar_view m_w_i;  //!< water mass sum N n S rho_w V, kg
    scalar_view vol_i;  //!< mixture volume sum N V, m^3
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

    WaterGridViews() = default;

    explicit WaterGridViews( const physics::GridGeometry& grid )
        : m_w_i( "m_w_i", grid.nx + 1, grid.ny + 1 )
        , vol_i( "vol_i", grid.nx + 1, grid.ny + 1 )
        , mv_w_i( "mv_w_i", grid.nx + 1, grid.ny + 1 )
        , f_w_i( "f_w_i", grid.nx + 1, grid.ny + 1 )
        , q_i( "q_i", grid.nx + 1, grid.ny + 1 )
        , v_w_i( "v_w_i", grid.nx + 1, grid.ny + 1 )
        , dv_w_i( "dv_w_i", grid.nx + 1, grid.ny + 1 )
        , flags_w_i( "flags_w_i", grid.nx + 1, grid.ny + 1 )
        , div_w_c( "div_w_c", grid.nx, grid.ny )
    {
    }
};

//---------------------------------------------------------------------------//
//! Calls f(name, view) for every View of WaterParticleViews (as
//! forEachParticleView).
template <class Views, class F>
void forEachWaterParticleView( Views& wv, F&& f )
{
    f( "p_w_p", wv.p_w_p );
    f( "S_p", wv.S_p );
    f( "dS_dp_p", wv.dS_dp_p );
    f( "k_rel_p", wv.k_rel_p );
    f( "n_p", wv.n_p );
    f( "v_w_p", wv.v_w_p );
    f( "div_v_w_p", wv.div_v_w_p );
    f( "p_w_condition_p", wv.p_w_condition_p );
    f( "inflow_p", wv.inflow_p );
    f( "p_w_held_p", wv.p_w_held_p );
    f( "inflow_weight_p", wv.inflow_weight_p );
}

} // namespace mpm

#endif // MPM_WATER_VIEWS_HPP
