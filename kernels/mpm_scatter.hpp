#ifndef MPM_SCATTER_HPP
#define MPM_SCATTER_HPP

#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp> // the Duplication and Contribution tags

#include <type_traits>

namespace mpm
{
//! Default scatter duplication per backend: plain adds on Serial, one
//! private copy per thread on OpenMP. Kernels take it as a template
//! parameter so benchmarks can compare against atomics.
template <class ExecSpace>
struct ScatterDuplication
{
    using type = Kokkos::Experimental::ScatterNonDuplicated;
};
#ifdef KOKKOS_ENABLE_OPENMP
template <>
struct ScatterDuplication<Kokkos::OpenMP>
{
    using type = Kokkos::Experimental::ScatterDuplicated;
};
#endif

//! Duplicated copies need no atomics; a shared copy does (except on Serial).
template <class ExecSpace, class Duplication>
using ScatterContribution = typename std::conditional<
    std::is_same<Duplication, Kokkos::Experimental::ScatterDuplicated>::value ||
        std::is_same<ExecSpace, Kokkos::Serial>::value,
    Kokkos::Experimental::ScatterNonAtomic,
    Kokkos::Experimental::ScatterAtomic>::type;

} // namespace mpm

#endif // MPM_SCATTER_HPP
