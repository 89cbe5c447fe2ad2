#include <solver/mpm_initial_stress.hpp>

#include <gtest/gtest.h>

namespace
{
using Host = Kokkos::DefaultHostExecutionSpace;

// Two columns of 0.5 m points (3 and 1 points high, tops at y = 1.5 and
// 0.5) of a saturated soil: rho dy per point = (m_s + n rho_w V) / w.
// Hand-computed: sigma_v = -g (weight above + half its own) per metre of
// width; sigma' = (K0 sigma_v + p_w, sigma_v + p_w, 0, K0 sigma_v + p_w).
TEST( GeostaticStress, column_weight_with_k0_and_bishop_suction_share )
{
    const double w = 0.5, g = 10.0, k0 = 0.6, m_s = 400.0, n = 0.3;
    const double vol = w * w, p_w = -8.0e3;
    const double x[4][2] = {
        { 0.25, 0.25 }, { 0.25, 1.25 }, { 0.25, 0.75 }, { 0.75, 0.25 } };
    mpm::ParticleViews<Host> pv( 4 );
    mpm::WaterParticleViews<Host> wv( 4 );
    for ( int p = 0; p < 4; ++p )
    {
        pv.x_p( p, 0 ) = x[p][0];
        pv.x_p( p, 1 ) = x[p][1];
        pv.m_p( p ) = m_s;
        pv.vol_p( p ) = vol;
        pv.status_p( p ) = mpm::point_active;
        pv.material_p( p ) = 0;
        wv.p_w_p( p ) = p_w;
        wv.n_p( p ) = n;
    }
    mpm::physics::MaterialTable materials;
    materials.size = 1;
    mpm::physics::WaterParams water;
    water.density = 1000.0;
    const mpm::PointLattice lattice{ 0.0, 0.0, 2.0 * w, 2 };
    mpm::setGeostaticStress( k0, g, lattice, materials, water, false, pv, wv );

    const double own = g * ( m_s + n * water.density * vol ) / w; // Pa
    // Depth in points: 2.5 (bottom of the tall column), 0.5 (its top),
    // 1.5 (its middle), 0.5 (the short column).
    const double depth_in_points[4] = { 2.5, 0.5, 1.5, 0.5 };
    for ( int p = 0; p < 4; ++p )
    {
        const double sigma_v = -own * depth_in_points[p];
        EXPECT_NEAR( pv.sigma_p( p, 1 ), sigma_v + p_w, 1e-9 ) << p;
        EXPECT_NEAR( pv.sigma_p( p, 0 ), k0 * sigma_v + p_w, 1e-9 ) << p;
        EXPECT_NEAR( pv.sigma_p( p, 3 ), k0 * sigma_v + p_w, 1e-9 ) << p;
        EXPECT_EQ( pv.sigma_p( p, 2 ), 0.0 ) << p;
    }
}

// A dry point has no suction share and only its own mass.
TEST( GeostaticStress, dry_points_carry_the_total_stress )
{
    mpm::ParticleViews<Host> pv( 2 );
    mpm::WaterParticleViews<Host> no_water;
    const double y[2] = { 0.25, 0.75 };
    for ( int p = 0; p < 2; ++p )
    {
        pv.x_p( p, 0 ) = 1.25;
        pv.x_p( p, 1 ) = y[p];
        pv.m_p( p ) = 500.0;
        pv.status_p( p ) = mpm::point_active;
    }
    pv.status_p( 1 ) = mpm::point_removed;
    mpm::physics::MaterialTable materials;
    mpm::physics::WaterParams water;
    mpm::setGeostaticStress( 0.5, 9.81, mpm::PointLattice{ 0.0, 0.0, 1.0, 2 },
                             materials, water, false, pv, no_water );
    // The removed point above adds no weight.
    EXPECT_NEAR( pv.sigma_p( 0, 1 ), -0.5 * 9.81 * 500.0 / 0.5, 1e-9 );
    EXPECT_NEAR( pv.sigma_p( 0, 0 ), -0.25 * 9.81 * 500.0 / 0.5, 1e-9 );
}

} // namespace
