#ifndef MPM_TEST_PRESSURE_TERMS_HPP
#define MPM_TEST_PRESSURE_TERMS_HPP

#include <mpm_pressure_terms.hpp>

namespace mpm_test
{
//! The pressure equation's cell and node sums (pressurePointTerms, taken by
//! takePressureCellTerms) of points without an inflow source.
template <class ExecSpace>
mpm::PressurePointTerms<ExecSpace> pressureTermsWithoutSource(
    const mpm::physics::GridGeometry& grid,
    const mpm::ParticleViews<ExecSpace>& points,
    const mpm::WaterParticleViews<ExecSpace>& water_points,
    const mpm::GridViews<ExecSpace>& nodes,
    const mpm::WaterGridViews<ExecSpace>& water_nodes )
{
    mpm::PressurePointTerms<ExecSpace> terms( grid );
    const auto no_source = KOKKOS_LAMBDA( const int ) { return 0.0; };
    mpm::pressurePointTerms( ExecSpace(), points, water_points, nodes,
                             water_nodes, mpm::physics::WaterParams{},
                             no_source, terms );
    mpm::takePressureCellTerms( ExecSpace(), grid, terms );
    return terms;
}
} // namespace mpm_test

#endif // MPM_TEST_PRESSURE_TERMS_HPP
