// The seepage step's own kernels (kernels/mpm_seepage.hpp).
#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_seepage.hpp>
#include <mpm_status_flags.hpp>
#include <mpm_test_backends.hpp>
#include <mpm_water_views.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

namespace
{
MPM_TEST_BACKEND_SUITE( SeepageKernels );

// Every node's solid fixed in x and y, its other flags (here the water's
// bits and a partial fixity) kept.
TYPED_TEST( SeepageKernels, held_flags_fix_the_solid_and_keep_the_rest )
{
    using memory = typename TypeParam::memory_space;
    Kokkos::View<int**, memory> flags( "flags", 3, 2 ), held( "held", 3, 2 );
    flags( 0, 0 ) = 0;
    flags( 1, 0 ) = mpm::node_fix_x;
    flags( 2, 1 ) = 1 << 6;
    mpm::holdSolidFlags( TypeParam(), flags, held );
    Kokkos::fence();
    const int fixed = mpm::node_fix_x | mpm::node_fix_y;
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 2; ++j )
            EXPECT_EQ( held( i, j ), flags( i, j ) | fixed ) << i << ", " << j;
    EXPECT_EQ( flags( 1, 0 ), mpm::node_fix_x ); // the stage's flags unchanged
}

// The largest saturation change over the active points whose p_w is free:
// a prescribed point (whose S a condition sets) and a removed one do not
// count; no free point gives 0.
TYPED_TEST( SeepageKernels, saturation_change_skips_prescribed_and_removed )
{
    mpm::ParticleViews<TypeParam> pv( 4 );
    mpm::WaterParticleViews<TypeParam> wv( 4 );
    Kokkos::View<double*, typename TypeParam::memory_space> before( "before",
                                                                    4 );
    const double S_before[4] = { 0.5, 0.5, 0.5, 0.5 };
    const double S_after[4] = { 0.52, 0.47, 0.9, 0.1 };
    for ( int p = 0; p < 4; ++p )
    {
        pv.status_p( p ) = mpm::point_active;
        wv.p_w_condition_p( p ) = -1;
        before( p ) = S_before[p];
        wv.S_p( p ) = S_after[p];
    }
    wv.p_w_condition_p( 2 ) = 0;           // prescribed: moved by 0.4
    pv.status_p( 3 ) = mpm::point_removed; // removed: moved by 0.4
    EXPECT_NEAR( mpm::maxSaturationChange( TypeParam(), pv, wv, before ), 0.03,
                 1.0e-15 );
    wv.p_w_condition_p( 0 ) = wv.p_w_condition_p( 1 ) = 0;
    EXPECT_EQ( mpm::maxSaturationChange( TypeParam(), pv, wv, before ), 0.0 );
}

} // namespace
