#include <mpm_test_backends.hpp>
#include <mpm_test_fixtures.hpp>

#include <mpm_g2p.hpp>
#include <solver/steps/mpm_dry_step_phases.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace
{
MPM_TEST_BACKEND_SUITE( Transfer );

// The dry step's phases as DryStep::advance runs them
// (mpm::DryStepPhases: the P2G scatter into sums kept between steps, the
// grid update that takes them, G2P with the remap scatter, the remap, the
// last point loop), on the test's points, grid and material.
template <class ExecSpace>
struct DryStep
{
    mpm::ParticleViews<ExecSpace> pv;
    mpm::GridViews<ExecSpace> gv;
    mpm::DryStepPhases<ExecSpace> phases;
    mpm::physics::MaterialTable materials;

    DryStep( const mpm::ParticleViews<ExecSpace>& points,
             const mpm::physics::GridGeometry& grid )
        : pv( points )
        , gv( grid )
        , phases( grid )
    {
        materials.materials[0] =
            mpm::physics::elasticParams( 1.0e7, 0.3, 1800.0 );
        materials.size = 1;
    }

    //! P2G and the grid update (their nodal m_i, p_i, f_i, v_i, dv_i).
    void scatterAndUpdateGrid( const double gravity_y, const double dt )
    {
        phases.scatter( ExecSpace(), pv, gv.geometry, 0.0, gravity_y,
                        mpm::LoadForceView<ExecSpace>( "no_loads", 0 ) );
        phases.updateGrid( ExecSpace(), gv, dt, 0.0, 1.0 );
    }
    //! G2P (with the remap scatter) and the remap.
    void gatherAndRemap( const double dt, const double flip_fraction )
    {
        phases.gatherAndRemap( ExecSpace(), pv, gv, dt, flip_fraction );
    }
    //! Velocity gradient, stress, positions and diagnostics.
    mpm::PointUpdateReport updatePoints( const double dt )
    {
        return phases.updatePoints( ExecSpace(), pv, gv, materials, dt, false,
                                    false );
    }
};

//! A host copy of `view` that later kernels do not change (a mirror view
//! of a host View would be the View itself).
template <class ViewType>
typename ViewType::HostMirror hostCopy( const ViewType& view )
{
    auto copy = Kokkos::create_mirror( view );
    Kokkos::deep_copy( copy, view );
    return copy;
}

//! Sums of the nodal mass, momentum and force.
template <class ExecSpace>
std::array<double, 5> nodalTotals( const mpm::GridViews<ExecSpace>& gv )
{
    const auto m_i = hostCopy( gv.m_i );
    const auto p_i = hostCopy( gv.p_i );
    const auto f_i = hostCopy( gv.f_i );
    std::array<double, 5> total{};
    for ( int i = 0; i <= gv.geometry.nx; ++i )
        for ( int j = 0; j <= gv.geometry.ny; ++j )
        {
            total[0] += m_i( i, j );
            total[1] += p_i( i, j, 0 );
            total[2] += p_i( i, j, 1 );
            total[3] += f_i( i, j, 0 );
            total[4] += f_i( i, j, 1 );
        }
    return total;
}

//---------------------------------------------------------------------------//
// P2G then sum over nodes conserves mass and momentum to round-off.
TYPED_TEST( Transfer, p2g_conserves_mass_and_momentum )
{
    using exec_space = TypeParam;
    const auto grid = mpm_test::makeGrid( 17, 13, 0.25 );
    const int num_p = 5000;
    mpm::ParticleViews<exec_space> pv( num_p );
    Kokkos::Random_XorShift64_Pool<exec_space> pool( 12345 );
    Kokkos::fill_random( pv.x_p, pool, 0.0, 3.2 ); // inside 4.25 x 3.25
    Kokkos::fill_random( pv.v_p, pool, -2.0, 3.0 );
    Kokkos::fill_random( pv.m_p, pool, 0.5, 1.5 );
    Kokkos::deep_copy( pv.vol_p, 0.01 );
    Kokkos::deep_copy( pv.status_p, mpm::point_active );
    DryStep<exec_space> step( pv, grid );
    // Twice: the grid update takes (and clears) the sums it uses.
    step.scatterAndUpdateGrid( -9.81, 0.0 );
    const auto first = nodalTotals( step.gv );
    step.scatterAndUpdateGrid( -9.81, 0.0 );
    const auto total = nodalTotals( step.gv );

    double m_p_sum = 0.0, px_p_sum = 0.0, py_p_sum = 0.0;
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<exec_space>( 0, num_p ),
        KOKKOS_LAMBDA( const int p, double& m, double& px, double& py ) {
            m += pv.m_p( p );
            px += pv.m_p( p ) * pv.v_p( p, 0 );
            py += pv.m_p( p ) * pv.v_p( p, 1 );
        },
        m_p_sum, px_p_sum, py_p_sum );
    for ( int k = 0; k < 5; ++k )
        EXPECT_NEAR( total[k], first[k], 1e-12 * 10.0 * m_p_sum );
    const double m_sum = total[0], px_sum = total[1], py_sum = total[2],
                 fy_sum = total[4];
    EXPECT_NEAR( total[3], 0.0, 1e-12 * 9.81 * m_p_sum );
    EXPECT_NEAR( m_sum, m_p_sum, 1e-12 * m_p_sum );
    EXPECT_NEAR( px_sum, px_p_sum, 1e-12 * std::abs( m_p_sum ) * 3.0 );
    EXPECT_NEAR( py_sum, py_p_sum, 1e-12 * std::abs( m_p_sum ) * 3.0 );
    // Zero stress: the nodal forces are the weight.
    EXPECT_NEAR( fy_sum, -9.81 * m_p_sum, 1e-12 * 9.81 * m_p_sum );
}

//---------------------------------------------------------------------------//
// A whole dry step of stress-free points in uniform motion, without
// gravity, with any FLIP fraction: P2G, grid update, G2P, remap and the
// point loop keep the velocity, strain nothing and move every point by
// dt v; the step's diagnostics report the kinetic energy.
TYPED_TEST( Transfer, uniform_motion_is_kept_by_the_whole_step )
{
    using exec_space = TypeParam;
    const auto grid = mpm_test::makeGrid( 8, 7, 0.5 );
    auto pv = mpm_test::gaussPoints<exec_space>( grid, 2, 6, 2, 5, 1800.0 );
    const double v[2] = { 0.8, -0.3 };
    auto v_h = Kokkos::create_mirror( pv.v_p );
    for ( int p = 0; p < pv.size(); ++p )
        for ( int d = 0; d < 2; ++d )
            v_h( p, d ) = v[d];
    Kokkos::deep_copy( pv.v_p, v_h );
    const auto x = hostCopy( pv.x_p );
    DryStep<exec_space> step( pv, grid );
    const double dt = 1.0e-3;
    step.scatterAndUpdateGrid( 0.0, dt );
    step.gatherAndRemap( dt, 0.7 );
    const mpm::PointUpdateReport report = step.updatePoints( dt );

    const auto x_new = hostCopy( pv.x_p );
    const auto v_new = hostCopy( pv.v_p );
    const auto L = hostCopy( pv.grad_v_p );
    const auto sigma = hostCopy( pv.sigma_p );
    const auto m = hostCopy( pv.m_p );
    double energy = 0.0;
    for ( int p = 0; p < pv.size(); ++p )
    {
        for ( int d = 0; d < 2; ++d )
        {
            EXPECT_NEAR( v_new( p, d ), v[d], 1e-14 ) << "p " << p;
            EXPECT_NEAR( x_new( p, d ), x( p, d ) + dt * v[d], 1e-15 );
            EXPECT_NEAR( L( p, d, 0 ), 0.0, 1e-12 );
            EXPECT_NEAR( L( p, d, 1 ), 0.0, 1e-12 );
        }
        for ( int c = 0; c < 4; ++c )
            EXPECT_NEAR( sigma( p, c ), 0.0, 1e-3 ) << "p " << p;
        energy += 0.5 * m( p ) * ( v[0] * v[0] + v[1] * v[1] );
    }
    EXPECT_EQ( report.first_outside, -1 );
    EXPECT_EQ( report.num_removed, 0 );
    EXPECT_NEAR( report.diagnostics.kinetic_energy, energy, 1e-12 * energy );
}

//---------------------------------------------------------------------------//
// A linear nodal velocity field is interpolated exactly (PIC) and its
// gradient is recovered exactly at every point.
TYPED_TEST( Transfer, g2p_of_linear_field_is_exact )
{
    using exec_space = TypeParam;
    const auto grid = mpm_test::makeGrid( 6, 5, 0.5 );
    auto pv = mpm_test::gaussPoints<exec_space>( grid, 1, 5, 1, 4, 2000.0 );
    DryStep<exec_space> step( pv, grid );
    auto& gv = step.gv;
    // v(x) = a + B x
    const double a[2] = { 0.3, -0.7 };
    const double B[2][2] = { { 0.11, -0.23 }, { 0.05, 0.17 } };
    auto v_h = Kokkos::create_mirror( gv.v_i );
    for ( int i = 0; i <= grid.nx; ++i )
        for ( int j = 0; j <= grid.ny; ++j )
            for ( int d = 0; d < 2; ++d )
                v_h( i, j, d ) = a[d] + B[d][0] * grid.nodeX( i ) +
                                 B[d][1] * grid.nodeY( j );
    Kokkos::deep_copy( gv.v_i, v_h );
    Kokkos::deep_copy( gv.dv_i, 0.0 );

    const double dt = 1.0e-3;
    const auto x = hostCopy( pv.x_p );
    // G2P (PIC) and the point loop on the linear field (no remap: the
    // remap projects it, exact only for a uniform field).
    mpm::g2pVelocityRemap( exec_space(), pv, gv, dt, 0.0,
                           step.phases.momentum_sums );
    step.updatePoints( dt );

    const auto x_new = hostCopy( pv.x_p );
    const auto v = hostCopy( pv.v_p );
    const auto du = hostCopy( pv.du_p );
    const auto L = hostCopy( pv.grad_v_p );
    for ( int p = 0; p < pv.size(); ++p )
        for ( int d = 0; d < 2; ++d )
        {
            const double exact =
                a[d] + B[d][0] * x( p, 0 ) + B[d][1] * x( p, 1 );
            EXPECT_NEAR( v( p, d ), exact, 1e-14 );
            EXPECT_NEAR( du( p, d ), dt * exact, 1e-17 );
            EXPECT_NEAR( x_new( p, d ), x( p, d ) + dt * exact, 1e-15 );
            EXPECT_NEAR( L( p, d, 0 ), B[d][0], 1e-13 );
            EXPECT_NEAR( L( p, d, 1 ), B[d][1], 1e-13 );
        }
}

//---------------------------------------------------------------------------//
// Patch test: a uniform strain increment gives a uniform stress, and a
// uniform stress gives zero internal force at the interior nodes.
TYPED_TEST( Transfer, uniform_strain_patch_test )
{
    using exec_space = TypeParam;
    const auto grid = mpm_test::makeGrid( 6, 6, 0.25 );
    auto pv = mpm_test::gaussPoints<exec_space>( grid, 1, 5, 1, 5, 1800.0 );
    const double B[2][2] = { { 1.0e-3, 4.0e-4 }, { -2.0e-4, -2.0e-3 } };
    DryStep<exec_space> step( pv, grid );
    auto& gv = step.gv;
    auto v_h = Kokkos::create_mirror( gv.v_i );
    for ( int i = 0; i <= grid.nx; ++i )
        for ( int j = 0; j <= grid.ny; ++j )
            for ( int d = 0; d < 2; ++d )
                v_h( i, j, d ) =
                    B[d][0] * grid.nodeX( i ) + B[d][1] * grid.nodeY( j );
    Kokkos::deep_copy( gv.v_i, v_h );

    const auto& materials = step.materials;
    const double dt = 1.0;
    // The point loop: gradient and stress (du_p = 0: no point moves).
    step.updatePoints( dt );

    const double K = materials[0].bulk_modulus;
    const double G = materials[0].shear_modulus;
    const double de[3] = { B[0][0] * dt, B[1][1] * dt,
                           0.5 * ( B[0][1] + B[1][0] ) * dt };
    const double tr = de[0] + de[1];
    const double expected[4] = { K * tr + 2.0 * G * ( de[0] - tr / 3.0 ),
                                 K * tr + 2.0 * G * ( de[1] - tr / 3.0 ),
                                 2.0 * G * de[2],
                                 K * tr + 2.0 * G * ( -tr / 3.0 ) };
    const auto s = hostCopy( pv.sigma_p );
    const double scale = std::abs( expected[1] );
    for ( int p = 0; p < pv.size(); ++p )
        for ( int c = 0; c < 4; ++c )
        {
            // The Jaumann rotation of the zero initial stress is zero.
            EXPECT_NEAR( s( p, c ), expected[c], 1e-12 * scale )
                << "p " << p << " c " << c;
        }

    // Uniform stress: interior nodes feel no internal force.
    step.scatterAndUpdateGrid( 0.0, 0.0 );
    const auto f = hostCopy( gv.f_i );
    double boundary_force = 0.0;
    for ( int i = 1; i <= 5; ++i )
        for ( int j = 1; j <= 5; ++j )
        {
            const bool interior = i > 1 && i < 5 && j > 1 && j < 5;
            if ( interior )
            {
                EXPECT_NEAR( f( i, j, 0 ), 0.0, 1e-10 * scale * grid.h );
                EXPECT_NEAR( f( i, j, 1 ), 0.0, 1e-10 * scale * grid.h );
            }
            else
                boundary_force += std::abs( f( i, j, 1 ) );
        }
    // ... while the boundary nodes carry the traction sigma . n.
    EXPECT_GT( boundary_force, 0.1 * scale * grid.h );
}

} // namespace
