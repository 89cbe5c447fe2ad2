#ifndef MPM_PRESSURE_ASSEMBLY_HPP
#define MPM_PRESSURE_ASSEMBLY_HPP

#include <mpm_device_type.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_scatter.hpp>
#include <mpm_status_flags.hpp>
#include <mpm_stencil_cg.hpp>
#include <physics/mpm_grid_geometry.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>

namespace mpm
{
/*!
  \brief Assembles the nodal pressure operator of the semi-implicit step
  (docs/formulation.md §9, item 3) from the active points into s.a:
    a(I, J) = Dt sum_p V_p M_p grad N_I(x_p) . grad N_J(x_p)
              + delta_IJ sum_p N_I(x_p) C_p V_p / Dt,
  M_p the point's mobility (m^2 / (Pa s)) and C_p its storage (1/Pa), for
  the 4 nodes of each point's cell and the 4 they couple with (9-point
  stencil). A scatter: one private copy per thread on OpenMP, plain adds on
  Serial. The coefficients are overwritten; s.nodes is left to the caller.
*/
template <class ExecSpace,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
void assemblePressureStencil(
    const ExecSpace& exec, const ParticleViews<ExecSpace>& pv,
    const Kokkos::View<double*, DeviceType<ExecSpace>>& mobility_p,
    const Kokkos::View<double*, DeviceType<ExecSpace>>& storage_p,
    const physics::GridGeometry& grid, const double dt,
    NodeStencilSystem<ExecSpace>& s )
{
    using Contribution = ScatterContribution<ExecSpace, Duplication>;
    Kokkos::deep_copy( exec, s.a, 0.0 );
    auto a_sv = Kokkos::Experimental::create_scatter_view<
        Kokkos::Experimental::ScatterSum, Duplication, Contribution>( s.a );
    const auto x_p = unmanaged( pv.x_p );
    const auto vol_p = unmanaged( pv.vol_p );
    const auto status_p = unmanaged( pv.status_p );
    const auto m_p = unmanaged( mobility_p );
    const auto c_p = unmanaged( storage_p );
    Kokkos::parallel_for(
        "pressure_assembly",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p ) {
            if ( status_p( p ) != point_active )
                return;
            int ci, cj;
            double w[4], dwdx[4], dwdy[4];
            grid.weights( x_p( p, 0 ), x_p( p, 1 ), ci, cj, w, dwdx, dwdy );
            const double flow = dt * vol_p( p ) * m_p( p );
            const double store = c_p( p ) * vol_p( p ) / dt;
            auto a = a_sv.access();
            for ( int k = 0; k < 4; ++k )
            {
                const int i = ci + k % 2, j = cj + k / 2;
                a( i, j, 4 ) += store * w[k];
                for ( int l = 0; l < 4; ++l )
                {
                    // Node l seen from node k: offsets in {-1, 0, 1}.
                    const int di = l % 2 - k % 2, dj = l / 2 - k / 2;
                    a( i, j, 3 * ( di + 1 ) + dj + 1 ) +=
                        flow * ( dwdx[k] * dwdx[l] + dwdy[k] * dwdy[l] );
                }
            }
        } );
    Kokkos::Experimental::contribute( s.a, a_sv );
}

} // namespace mpm

#endif // MPM_PRESSURE_ASSEMBLY_HPP
