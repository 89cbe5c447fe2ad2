// Benchmark driver (the kokkos-kernels pattern): Kokkos owns its flags
// (--kokkos-threads=N), Google Benchmark the rest.

#include <Kokkos_Core.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
//! Value of an environment variable, or "unset".
std::string environment( const char* name )
{
    const char* value = std::getenv( name );
    return value ? value : "unset";
}

//! Kokkos version as "3.4.01".
std::string kokkosVersion()
{
    char text[32];
    std::snprintf( text, sizeof( text ), "%d.%d.%02d", KOKKOS_VERSION / 10000,
                   KOKKOS_VERSION / 100 % 100, KOKKOS_VERSION % 100 );
    return text;
}

} // namespace

int main( int argc, char* argv[] )
{
    Kokkos::ScopeGuard guard( argc, argv );
    benchmark::Initialize( &argc, argv );
    if ( benchmark::ReportUnrecognizedArguments( argc, argv ) )
        return 1;

    // Context block: what the numbers were measured on.
    benchmark::AddCustomContext( "kokkos_version", kokkosVersion() );
#ifdef KOKKOS_ENABLE_OPENMP
    benchmark::AddCustomContext(
        "openmp_threads", std::to_string( Kokkos::OpenMP::concurrency() ) );
#endif
    benchmark::AddCustomContext( "OMP_PROC_BIND",
                                 environment( "OMP_PROC_BIND" ) );
    benchmark::AddCustomContext( "OMP_PLACES", environment( "OMP_PLACES" ) );
    benchmark::AddCustomContext( "compiler", "g++ " __VERSION__ );
    benchmark::AddCustomContext(
        "problem", "Mohr-Coulomb block 2H x H (H = 10 m) on a fixed base, "
                   "2x2 points per cell, geostatic stress + 0.03 s of "
                   "gravity; arg = cells across H" );

    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
