#ifndef MPM_TEST_PRESSURE_TERMS_HPP
#define MPM_TEST_PRESSURE_TERMS_HPP

#include <mpm_pressure_terms.hpp>

namespace mpm_test
{
//! Sets the volumes vol (m^3), saturations S and p_w conditions (-1: free)
//! of the first num_points points.
template <class ExecSpace>
void setPointWater( const mpm::ParticleViews<ExecSpace>& points,
                    const mpm::WaterParticleViews<ExecSpace>& water_points,
                    const int num_points, const double vol[], const double S[],
                    const int condition[] )
{
    auto vol_h = Kokkos::create_mirror_view( points.vol_p );
    auto S_h = Kokkos::create_mirror_view( water_points.S_p );
    auto condition_h =
        Kokkos::create_mirror_view( water_points.p_w_condition_p );
    for ( int p = 0; p < num_points; ++p )
    {
        vol_h( p ) = vol[p];
        S_h( p ) = S[p];
        condition_h( p ) = condition[p];
    }
    Kokkos::deep_copy( points.vol_p, vol_h );
    Kokkos::deep_copy( water_points.S_p, S_h );
    Kokkos::deep_copy( water_points.p_w_condition_p, condition_h );
}

//! The pressure equation's cell and node sums (pressurePointTerms) of
//! points without an inflow source.
template <class ExecSpace>
mpm::PressurePointTerms<ExecSpace> pressureTermsWithoutSource(
    const mpm::physics::GridGeometry& grid,
    const mpm::ParticleViews<ExecSpace>& points,
    const mpm::WaterParticleViews<ExecSpace>& water_points,
    const mpm::GridViews<ExecSpace>& nodes,
    const mpm::WaterGridViews<ExecSpace>& water_nodes )
{
    mpm::PressurePointTerms<ExecSpace> terms( grid );
    mpm::CellPointLists<ExecSpace> lists( points.size(), grid.nx * grid.ny );
    const auto no_source = KOKKOS_LAMBDA( const int ) { return 0.0; };
    mpm::pressurePointTerms( ExecSpace(), points, water_points, nodes,
                             water_nodes, mpm::physics::WaterParams{},
                             no_source, lists, terms );
    return terms;
}
} // namespace mpm_test

#endif // MPM_TEST_PRESSURE_TERMS_HPP
