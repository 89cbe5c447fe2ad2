#ifndef MPM_PRESSURE_ASSEMBLY_HPP
#define MPM_PRESSURE_ASSEMBLY_HPP

#include <mpm_device_type.hpp>
#include <mpm_grid_scatter.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_point_stencil.hpp>
#include <mpm_stencil_cg.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! The point sums of the pressure operator's 9 stencil coefficients per
//! node (a GridScatter) and the list of the nodes they touched.
template <class ExecSpace>
struct PressureStencilSums
{
    GridScatter<ExecSpace, 9> sums;
    Kokkos::View<int*, DeviceType<ExecSpace>> touched;

    PressureStencilSums() = default;
    explicit PressureStencilSums( const physics::GridGeometry& grid )
        : sums( "pressure_stencil_sums", grid.numNodes() )
        , touched( "pressure_stencil_touched", grid.numNodes() )
    {
    }
};

/*!
  \brief Assembles the nodal pressure operator of the semi-implicit step
  (docs/formulation.md §9, item 3) from the active points into s.a:
    a(I, J) = Dt sum_p V_p M_p grad N_I(x_p) . grad N_J(x_p)
              + delta_IJ sum_p N_I(x_p) C_p V_p / Dt,
  M_p the point's mobility (m^2 / (Pa s)) and C_p its storage (1/Pa), for
  the 4 nodes of each point's cell and the 4 they couple with (9-point
  stencil). The points add into `sums` (one copy per thread on OpenMP,
  plain adds on Serial); the rows of the nodes they touch are then
  overwritten, and only those: a row no point touches keeps what it held
  (no unknown node is without points). s.nodes is left to the caller.
*/
template <class ExecSpace>
void assemblePressureStencil(
    const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
    const Kokkos::View<double*, DeviceType<ExecSpace>>& mobility_p,
    const Kokkos::View<double*, DeviceType<ExecSpace>>& storage_p,
    const physics::GridGeometry& grid, const double dt,
    PressureStencilSums<ExecSpace>& sums, NodeStencilSystem<ExecSpace>& s )
{
    const auto handle = sums.sums.handle();
    const auto vol_p = unmanaged( pv.vol_p );
    const auto m_p = unmanaged( mobility_p );
    const auto c_p = unmanaged( storage_p );
    const int ny1 = grid.ny + 1;
    forEachPointStencil(
        "mpm::pressure_assembly", exec, pv, grid,
        KOKKOS_LAMBDA( const int p, const PointStencil& stencil ) {
            const auto& [ci, cj, w, dwdx, dwdy] = stencil;
            const double flow = dt * vol_p( p ) * m_p( p );
            const double store = c_p( p ) * vol_p( p ) / dt;
            auto access = handle.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int node = nodeIndex( ci + k % 2, cj + k / 2, ny1 );
                access.touch( node );
                access.add( node, 4, store * w[k] );
                for ( int l = 0; l < 4; ++l )
                {
                    // Node l seen from node k: offsets in {-1, 0, 1}.
                    const int di = l % 2 - k % 2, dj = l / 2 - k / 2;
                    access.add( node, 3 * ( di + 1 ) + dj + 1,
                                flow *
                                    ( dwdx[k] * dwdx[l] + dwdy[k] * dwdy[l] ) );
                }
            }
        } );
    const int count = sums.sums.listTouched( exec, sums.touched );
    const auto touched = unmanaged( sums.touched );
    const auto a = unmanaged( s.a );
    Kokkos::parallel_for(
        "mpm::pressure_stencil_rows",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, count ),
        KOKKOS_LAMBDA( const int m ) {
            const int node = touched( m );
            for ( int k = 0; k < 9; ++k )
                a( node / ny1, node % ny1, k ) = handle.take( node, k );
        } );
}

} // namespace mpm

#endif // MPM_PRESSURE_ASSEMBLY_HPP
