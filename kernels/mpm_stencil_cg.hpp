#ifndef MPM_STENCIL_CG_HPP
#define MPM_STENCIL_CG_HPP

//---------------------------------------------------------------------------//
// The pressure solve of a semi-implicit step (issue 13): a symmetric positive
// definite system over grid nodes with the 9-point stencil of bilinear shape
// functions, solved by Jacobi-preconditioned conjugate gradients, every
// operation a Kokkos kernel over the list of unknown nodes.
//---------------------------------------------------------------------------//

#include <mpm_device_type.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

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
    bool converged = false;
};

namespace Impl
{
//! y = A x over the unknowns (x = 0 off them, by construction).
template <class ExecSpace, class NodeView>
void applyStencil( const ExecSpace& exec, const NodeStencilSystem<ExecSpace>& s,
                   const NodeView& x, const NodeView& y )
{
    const auto a = unmanaged( s.a );
    const auto nodes = unmanaged( s.nodes );
    const auto xu = unmanaged( x );
    const auto yu = unmanaged( y );
    const int nx1 = static_cast<int>( a.extent( 0 ) );
    const int ny1 = static_cast<int>( a.extent( 1 ) );
    Kokkos::parallel_for(
        "cg_apply", Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m ) {
            const int n = nodes( m );
            const int i = n / ny1, j = n % ny1;
            double sum = 0.0;
            for ( int di = -1; di <= 1; ++di )
                for ( int dj = -1; dj <= 1; ++dj )
                {
                    const int ii = i + di, jj = j + dj;
                    if ( ii >= 0 && ii < nx1 && jj >= 0 && jj < ny1 )
                        sum +=
                            a( i, j, 3 * ( di + 1 ) + dj + 1 ) * xu( ii, jj );
                }
            yu( i, j ) = sum;
        } );
}

//! Sum over the unknowns of u v.
template <class ExecSpace, class NodeView>
double dotOverNodes( const ExecSpace& exec,
                     const NodeStencilSystem<ExecSpace>& s, const NodeView& u,
                     const NodeView& v )
{
    const auto nodes = unmanaged( s.nodes );
    const auto uu = unmanaged( u );
    const auto vu = unmanaged( v );
    const int ny1 = static_cast<int>( u.extent( 1 ) );
    double sum = 0.0;
    Kokkos::parallel_reduce(
        "cg_dot", Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m, double& acc ) {
            const int n = nodes( m );
            acc += uu( n / ny1, n % ny1 ) * vu( n / ny1, n % ny1 );
        },
        sum );
    return sum;
}
} // namespace Impl

/*!
  \brief Work vectors of the solve (residual r, preconditioned z, search
  direction p, A p); only their values on the unknowns are used, and p is
  zero off them.
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct CgWorkspace
{
    using view = Kokkos::View<double**, DeviceType<ExecSpace>, MemoryTraits>;
    view r, z, p, q;
    CgWorkspace() = default;
    CgWorkspace( const int nx, const int ny )
        : r( "cg_r", nx + 1, ny + 1 )
        , z( "cg_z", nx + 1, ny + 1 )
        , p( "cg_p", nx + 1, ny + 1 )
        , q( "cg_q", nx + 1, ny + 1 )
    {
    }
};

//! The work vectors without reference counting, for kernel closures.
template <class ExecSpace>
CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged>
unmanaged( const CgWorkspace<ExecSpace>& w )
{
    CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged> u;
    u.r = w.r;
    u.z = w.z;
    u.p = w.p;
    u.q = w.q;
    return u;
}

/*!
  \brief Solves A x = b over the unknowns by conjugate gradients with the
  Jacobi preconditioner M = diag(A) (A symmetric positive definite), from
  the x given (the previous step's pressure is a good start). Stops at
  |r| <= tolerance |b| or after max_iterations; x off the unknowns is left
  as it is.
*/
template <class ExecSpace, class NodeView>
CgReport
solveJacobiCg( const ExecSpace& exec, const NodeStencilSystem<ExecSpace>& s,
               const NodeView& b, const NodeView& x, CgWorkspace<ExecSpace>& w,
               const double tolerance, const int max_iterations )
{
    const auto a = unmanaged( s.a );
    const auto nodes = unmanaged( s.nodes );
    const auto bu = unmanaged( b );
    const auto xu = unmanaged( x );
    const auto v = unmanaged( w ); // r, z = M^-1 r, p, q = A p
    const int ny1 = static_cast<int>( x.extent( 1 ) );
    const auto policy = Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes );

    // r = b - A x (x copied into p on the unknowns only), z = M^-1 r, p = z.
    // Only p is read off the unknowns (as a neighbour in A p): zero it there.
    Kokkos::deep_copy( exec, w.p, 0.0 );
    Kokkos::parallel_for(
        "cg_copy_x", policy, KOKKOS_LAMBDA( const int m ) {
            const int n = nodes( m );
            v.p( n / ny1, n % ny1 ) = xu( n / ny1, n % ny1 );
        } );
    Impl::applyStencil( exec, s, w.p, w.q );
    Kokkos::parallel_for(
        "cg_start", policy, KOKKOS_LAMBDA( const int m ) {
            const int n = nodes( m );
            const int i = n / ny1, j = n % ny1;
            v.r( i, j ) = bu( i, j ) - v.q( i, j );
            v.z( i, j ) = v.r( i, j ) / a( i, j, 4 );
            v.p( i, j ) = v.z( i, j );
        } );

    CgReport report;
    report.rhs_norm =
        Kokkos::Experimental::sqrt( Impl::dotOverNodes( exec, s, b, b ) );
    const double target = tolerance * report.rhs_norm;
    double rz = Impl::dotOverNodes( exec, s, w.r, w.z );
    report.residual_norm =
        Kokkos::Experimental::sqrt( Impl::dotOverNodes( exec, s, w.r, w.r ) );
    while ( report.residual_norm > target &&
            report.iterations < max_iterations )
    {
        Impl::applyStencil( exec, s, w.p, w.q );
        const double alpha = rz / Impl::dotOverNodes( exec, s, w.p, w.q );
        Kokkos::parallel_for(
            "cg_update", policy, KOKKOS_LAMBDA( const int m ) {
                const int n = nodes( m );
                const int i = n / ny1, j = n % ny1;
                xu( i, j ) += alpha * v.p( i, j );
                v.r( i, j ) -= alpha * v.q( i, j );
                v.z( i, j ) = v.r( i, j ) / a( i, j, 4 );
            } );
        const double rz_new = Impl::dotOverNodes( exec, s, w.r, w.z );
        const double beta = rz_new / rz;
        rz = rz_new;
        Kokkos::parallel_for(
            "cg_direction", policy, KOKKOS_LAMBDA( const int m ) {
                const int n = nodes( m );
                const int i = n / ny1, j = n % ny1;
                v.p( i, j ) = v.z( i, j ) + beta * v.p( i, j );
            } );
        report.residual_norm = Kokkos::Experimental::sqrt(
            Impl::dotOverNodes( exec, s, w.r, w.r ) );
        ++report.iterations;
    }
    report.converged = report.residual_norm <= target;
    return report;
}

} // namespace mpm

#endif // MPM_STENCIL_CG_HPP
