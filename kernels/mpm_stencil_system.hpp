#ifndef MPM_STENCIL_SYSTEM_HPP
#define MPM_STENCIL_SYSTEM_HPP

//---------------------------------------------------------------------------//
// The system of the pressure solve (mpm_stencil_cg.hpp): a symmetric positive
// definite system over grid nodes with the 9-point stencil of bilinear shape
// functions, its stencil rows, sums over its unknowns and the conjugate
// gradients' work vectors.
//---------------------------------------------------------------------------//

#include <mpm_device_type.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace mpm
{
/*!
  \brief A node-based linear system A x = b: row n = i (ny + 1) + j of the
  node (i, j) couples it with its 8 neighbours, a(i, j, k) the coefficient
  of node (i + di, j + dj) with k = 3 (di + 1) + (dj + 1). Only the nodes of
  `nodes` (flat indices) are unknowns; every other node is held at 0 (a
  Dirichlet value is lifted into b by the caller).
*/
template <class ExecSpace>
struct NodeStencilSystem
{
    using device_type = DeviceType<ExecSpace>;
    Kokkos::View<double** [9], device_type> a;
    Kokkos::View<int*, device_type> nodes;
    int num_nodes = 0;

    NodeStencilSystem() = default;
    NodeStencilSystem( const int nx, const int ny, const int capacity )
        : a( "a_i", nx + 1, ny + 1 )
        , nodes( "cg_nodes", capacity )
    {
    }
};

//! Iterations and residual of a solve; the solve stops at
//! |b - A x| <= tolerance |b| (Euclidean norms over the unknowns).
struct CgReport
{
    int iterations = 0;
    double residual_norm = 0.0;
    double rhs_norm = 0.0;
    double tolerance = 0.0; //!< the solve's stopping ratio |r| / |b|
    bool converged = false;
};

/*!
  \brief The preconditioner M of a solve. Jacobi: M = diag(A). BlockDilu:
  the unknowns (in their list's order) split into `cg_blocks` blocks of
  equal count, and on each M = (P + L) P^-1 (P + L)^T with L the strictly
  lower part of A within the block and the pivots P chosen so that M and A
  share their diagonal, p_m = a_mm - sum over lower neighbours j of the
  block of a_mj a_jm / p_j (diagonal-based incomplete LU, "DILU"; a pivot
  below `cg_min_pivot` a_mm is taken as a_mm). M is symmetric positive
  definite for any positive pivots. On the slope's pressure systems it takes
  a third of Jacobi's iterations (docs/formulation.md §9). The blocks do not
  depend on the number of threads: each thread takes whole blocks.
*/
enum class CgPreconditioner
{
    BlockDilu,
    Jacobi
};

//! Where a solve starts: from the x given, or from x = 0 (x is set to 0
//! on the unknowns).
enum class CgStart
{
    Given,
    Zero
};

//! The number of DILU blocks (CgPreconditioner::BlockDilu).
constexpr int cg_blocks = 4;
//! The smallest DILU pivot kept, relative to the diagonal.
constexpr double cg_min_pivot = 0.05;

namespace Impl
{
//! Node n (flat index, nx1 x ny1 nodes) has all 8 neighbours in the grid.
KOKKOS_INLINE_FUNCTION bool isInteriorNode( const int n, const int nx1,
                                            const int ny1 )
{
    const int i = n / ny1, j = n % ny1;
    return i > 0 && i < nx1 - 1 && j > 0 && j < ny1 - 1;
}

//! Row n of the 9-point stencil times x, flat indices (ny1 nodes a column):
//! all 9 neighbours unchecked (an interior node).
KOKKOS_INLINE_FUNCTION double interiorRow( const double* a, const double* x,
                                           const int n, const int ny1 )
{
    const double* c = a + 9 * n;
    const double* left = x + n - ny1; // column i - 1: nodes j - 1, j, j + 1
    const double* here = x + n;
    const double* right = x + n + ny1;
    // The three columns' sums, then their sum.
    const double sum_left = c[0] * left[-1] + c[1] * left[0] + c[2] * left[1];
    const double sum_here = c[3] * here[-1] + c[4] * here[0] + c[5] * here[1];
    const double sum_right =
        c[6] * right[-1] + c[7] * right[0] + c[8] * right[1];
    return ( sum_left + sum_here ) + sum_right;
}

//! Row n of the 9-point stencil times x, neighbours outside the grid
//! (nx1 x ny1 nodes) skipped; without the diagonal term unless `diagonal`.
KOKKOS_INLINE_FUNCTION double edgeRow( const double* a, const double* x,
                                       const int n, const int nx1,
                                       const int ny1,
                                       const bool diagonal = true )
{
    const int i = n / ny1, j = n % ny1;
    double sum = 0.0;
    for ( int di = -1; di <= 1; ++di )
        for ( int dj = -1; dj <= 1; ++dj )
        {
            const int ii = i + di, jj = j + dj;
            if ( ( diagonal || di != 0 || dj != 0 ) && ii >= 0 && ii < nx1 &&
                 jj >= 0 && jj < ny1 )
                sum += a[9 * n + 3 * ( di + 1 ) + dj + 1] * x[ii * ny1 + jj];
        }
    return sum;
}

//! Row n of the 9-point stencil times x without its diagonal term: the
//! neighbours inside the grid (nx1 x ny1 nodes).
KOKKOS_INLINE_FUNCTION double neighbourSum( const double* a, const double* x,
                                            const int n, const int nx1,
                                            const int ny1 )
{
    return edgeRow( a, x, n, nx1, ny1, false );
}

//! Sum over the unknowns of s of term(n), n the unknown's flat index (one
//! reduction; term may also write that unknown's entries).
template <class ExecSpace, class Term>
double sumOverUnknowns( const char* label, const ExecSpace& exec,
                        const NodeStencilSystem<ExecSpace>& s,
                        const Term& term )
{
    const auto nodes = unmanaged( s.nodes );
    double sum = 0.0;
    Kokkos::parallel_reduce(
        label, Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m, double& acc ) {
            acc += term( nodes( m ) );
        },
        sum );
    return sum;
}

//! Sum over the unknowns of u v.
template <class ExecSpace, class NodeView>
double dotOverNodes( const ExecSpace& exec,
                     const NodeStencilSystem<ExecSpace>& s, const NodeView& u,
                     const NodeView& v )
{
    const auto uu = unmanaged( u );
    const auto vu = unmanaged( v );
    const int ny1 = static_cast<int>( u.extent( 1 ) );
    return sumOverUnknowns(
        "cg_dot", exec, s, KOKKOS_LAMBDA( const int n ) {
            return uu( n / ny1, n % ny1 ) * vu( n / ny1, n % ny1 );
        } );
}

//! Sum over the unknowns of |u|.
template <class ExecSpace, class NodeView>
double absSumOverNodes( const ExecSpace& exec,
                        const NodeStencilSystem<ExecSpace>& s,
                        const NodeView& u )
{
    const auto uu = unmanaged( u );
    const int ny1 = static_cast<int>( u.extent( 1 ) );
    return sumOverUnknowns(
        "cg_abs_sum", exec, s, KOKKOS_LAMBDA( const int n ) {
            return Kokkos::Experimental::fabs( uu( n / ny1, n % ny1 ) );
        } );
}
} // namespace Impl

/*!
  \brief Work vectors of the solve, over the unknowns in the order of the
  system's `nodes` (index m): residual r, w = A z, search direction p,
  s = A p and the inverses of the preconditioner's pivots (Jacobi: A's
  diagonal); the preconditioned residual z = M^-1 r over the grid nodes
  (read as a neighbour in A z: zero off the unknowns). `rows`: each
  unknown's flat node index and its flags (Impl::row_interior: all 8 of its
  neighbours lie inside the grid; Impl::row_in_block: also every one that
  is an unknown lies in its DILU block); `unknown_of`: each node's index m, -1
  off the unknowns (the last solve's; a solve clears only those);
  `partial`: each thread's share of an iteration's sums, two buffers of a
  row per thread, a row a cache line (no two threads write to one line);
  `result`: what a solve reports (TeamCg) and how many unknowns it had.
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct CgWorkspace
{
    using vector = Kokkos::View<double*, DeviceType<ExecSpace>, MemoryTraits>;
    using view = Kokkos::View<double**, DeviceType<ExecSpace>, MemoryTraits>;
    using sums_view =
        Kokkos::View<double* [8], DeviceType<ExecSpace>, MemoryTraits>;
    //! iterations, |r|^2, |b|^2, 1 if converged (else 0), the unknowns.
    using result_view =
        Kokkos::View<double[5], DeviceType<ExecSpace>, MemoryTraits>;
    vector r, w, p, s, inverse_pivot;
    view z;
    Kokkos::View<int* [2], DeviceType<ExecSpace>, MemoryTraits> rows;
    Kokkos::View<int*, DeviceType<ExecSpace>, MemoryTraits> unknown_of;
    sums_view partial;
    result_view result;

    CgWorkspace() = default;
    CgWorkspace( const int nx, const int ny )
        : r( "cg_r", ( nx + 1 ) * ( ny + 1 ) )
        , w( "cg_w", ( nx + 1 ) * ( ny + 1 ) )
        , p( "cg_p", ( nx + 1 ) * ( ny + 1 ) )
        , s( "cg_s", ( nx + 1 ) * ( ny + 1 ) )
        , inverse_pivot( "cg_inverse_pivot", ( nx + 1 ) * ( ny + 1 ) )
        , z( "cg_z", nx + 1, ny + 1 )
        , rows( "cg_rows", ( nx + 1 ) * ( ny + 1 ) )
        , unknown_of( "cg_unknown_of", ( nx + 1 ) * ( ny + 1 ) )
        , partial( "cg_partial_sums", 2 * ExecSpace::concurrency() )
        , result( "cg_result" )
    {
        Kokkos::deep_copy( unknown_of, -1 );
    }
};

//! The work vectors without reference counting, for kernel closures.
template <class ExecSpace>
CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged>
unmanaged( const CgWorkspace<ExecSpace>& w )
{
    CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged> u;
    u.r = w.r;
    u.w = w.w;
    u.p = w.p;
    u.s = w.s;
    u.inverse_pivot = w.inverse_pivot;
    u.z = w.z;
    u.rows = w.rows;
    u.unknown_of = w.unknown_of;
    u.partial = w.partial;
    u.result = w.result;
    return u;
}

} // namespace mpm

#endif // MPM_STENCIL_SYSTEM_HPP
