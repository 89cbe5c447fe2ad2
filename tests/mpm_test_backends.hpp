#ifndef MPM_TEST_BACKENDS_HPP
#define MPM_TEST_BACKENDS_HPP

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <string>

namespace mpm_test
{
//! The execution spaces every typed test is instantiated on.
#if defined( KOKKOS_ENABLE_SERIAL ) && defined( KOKKOS_ENABLE_OPENMP )
using Backends = ::testing::Types<Kokkos::Serial, Kokkos::OpenMP>;
#elif defined( KOKKOS_ENABLE_OPENMP )
using Backends = ::testing::Types<Kokkos::OpenMP>;
#else
using Backends = ::testing::Types<Kokkos::Serial>;
#endif

//! Gives test names like Transfer/Serial.mass_is_conserved.
struct BackendName
{
    template <class ExecSpace>
    static std::string GetName( int )
    {
        return ExecSpace::name();
    }
};

//! Declares the empty fixture `Suite` of typed tests over the Backends.
#define MPM_TEST_BACKEND_SUITE( Suite )                                        \
    template <class ExecSpace>                                                 \
    class Suite : public ::testing::Test                                       \
    {                                                                          \
    };                                                                         \
    TYPED_TEST_SUITE( Suite, mpm_test::Backends, mpm_test::BackendName )

//! Relative difference |a - b| / max(|a|, |b|, floor).
inline double relativeDifference( const double a, const double b,
                                  const double floor = 1.0e-300 )
{
    const double scale = std::max( { std::abs( a ), std::abs( b ), floor } );
    return std::abs( a - b ) / scale;
}

} // namespace mpm_test

#endif // MPM_TEST_BACKENDS_HPP
