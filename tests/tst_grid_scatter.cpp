// GridScatter: point contributions summed per entry with every scatter
// strategy (plain, duplicated, atomic), touched entries listed, sums
// cleared by take() so the next step starts from zero.
#include <mpm_test_backends.hpp>

#include <mpm_grid_scatter.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( GridScatterTest );

//---------------------------------------------------------------------------//
//! Scatters contribution c(p, f) = p + f of point p to entry p % 7 (fields
//! f = 0, 1) over two steps; checks the sums, the touched list and that
//! take() leaves zero sums behind.
template <class ExecSpace, class Duplication>
void checkScatter()
{
    const int num_points = 1000;
    const int num_entries = 20; // entries 7..19 are never touched
    const mpm::GridScatter<ExecSpace, 2, Duplication> scatter( "sums",
                                                               num_entries );
    const auto sums = scatter.handle();
    Kokkos::View<int*, mpm::DeviceType<ExecSpace>> list( "list", num_entries );
    Kokkos::View<double* [2], mpm::DeviceType<ExecSpace>> taken( "taken",
                                                                 num_entries );
    for ( int step = 0; step < 2; ++step )
    {
        Kokkos::parallel_for(
            Kokkos::RangePolicy<ExecSpace>( 0, num_points ),
            KOKKOS_LAMBDA( const int p ) {
                const auto entry = sums.access();
                entry.touch( p % 7 );
                entry.add( p % 7, 0, p + 0.0 );
                entry.add( p % 7, 1, p + 1.0 );
            } );
        const int count = scatter.listTouched( ExecSpace(), list );
        ASSERT_EQ( count, 7 );
        Kokkos::parallel_for(
            Kokkos::RangePolicy<ExecSpace>( 0, count ),
            KOKKOS_LAMBDA( const int a ) {
                taken( list( a ), 0 ) = sums.take( list( a ), 0 );
                taken( list( a ), 1 ) = sums.take( list( a ), 1 );
            } );
        const auto list_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), list );
        const auto taken_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), taken );
        for ( int e = 0; e < 7; ++e )
        {
            EXPECT_EQ( list_h( e ), e );
            double expected[2] = { 0.0, 0.0 };
            for ( int p = e; p < num_points; p += 7 )
            {
                expected[0] += p;
                expected[1] += p + 1.0;
            }
            // Integer-valued sums are exact in any order.
            EXPECT_EQ( taken_h( e, 0 ), expected[0] ) << "step " << step;
            EXPECT_EQ( taken_h( e, 1 ), expected[1] ) << "step " << step;
        }
    }
    // Nothing left: no entry touched, every sum zero.
    EXPECT_EQ( scatter.listTouched( ExecSpace(), list ), 0 );
    double left = 0.0;
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<ExecSpace>( 0, num_entries ),
        KOKKOS_LAMBDA( const int e, double& sum ) {
            sum += Kokkos::Experimental::fabs( sums.take( e, 0 ) ) +
                   Kokkos::Experimental::fabs( sums.take( e, 1 ) );
        },
        left );
    EXPECT_EQ( left, 0.0 );
}

TYPED_TEST( GridScatterTest, default_strategy_sums_and_clears )
{
    checkScatter<TypeParam,
                 typename mpm::ScatterDuplication<TypeParam>::type>();
}

TYPED_TEST( GridScatterTest, shared_copy_sums_and_clears )
{
    // Atomics on a parallel backend, plain adds on Serial.
    checkScatter<TypeParam, Kokkos::Experimental::ScatterNonDuplicated>();
}

TYPED_TEST( GridScatterTest, one_copy_per_thread_sums_and_clears )
{
    checkScatter<TypeParam, Kokkos::Experimental::ScatterDuplicated>();
}

} // namespace
