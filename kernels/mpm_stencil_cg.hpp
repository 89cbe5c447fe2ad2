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
    double tolerance = 0.0; //!< the solve's stopping ratio |r| / |b|
    bool converged = false;
};

namespace Impl
{
//! (A x)_ij: row (i, j) of the 9-point stencil a times x (neighbours
//! outside the grid skipped).
template <class StencilView, class NodeView>
KOKKOS_INLINE_FUNCTION double
stencilRow( const StencilView& a, const NodeView& x, const int i, const int j )
{
    const int nx1 = static_cast<int>( a.extent( 0 ) );
    const int ny1 = static_cast<int>( a.extent( 1 ) );
    double sum = 0.0;
    for ( int di = -1; di <= 1; ++di )
        for ( int dj = -1; dj <= 1; ++dj )
        {
            const int ii = i + di, jj = j + dj;
            if ( ii >= 0 && ii < nx1 && jj >= 0 && jj < ny1 )
                sum += a( i, j, 3 * ( di + 1 ) + dj + 1 ) * x( ii, jj );
        }
    return sum;
}

//! y = A x over the unknowns (x = 0 off them, by construction).
template <class ExecSpace, class NodeView>
void applyStencil( const ExecSpace& exec, const NodeStencilSystem<ExecSpace>& s,
                   const NodeView& x, const NodeView& y )
{
    const auto a = unmanaged( s.a );
    const auto nodes = unmanaged( s.nodes );
    const auto xu = unmanaged( x );
    const auto yu = unmanaged( y );
    const int ny1 = static_cast<int>( a.extent( 1 ) );
    Kokkos::parallel_for(
        "cg_apply", Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes ),
        KOKKOS_LAMBDA( const int m ) {
            const int i = nodes( m ) / ny1, j = nodes( m ) % ny1;
            yu( i, j ) = stencilRow( a, xu, i, j );
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
  \brief Work vectors of the solve: residual r, preconditioned residual
  z = M^-1 r, w = A z, search direction p and s = A p; only their values on
  the unknowns are used, and z is zero off them (it is read as a neighbour
  in A z).
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct CgWorkspace
{
    using view = Kokkos::View<double**, DeviceType<ExecSpace>, MemoryTraits>;
    view r, z, w, p, s;
    CgWorkspace() = default;
    CgWorkspace( const int nx, const int ny )
        : r( "cg_r", nx + 1, ny + 1 )
        , z( "cg_z", nx + 1, ny + 1 )
        , w( "cg_w", nx + 1, ny + 1 )
        , p( "cg_p", nx + 1, ny + 1 )
        , s( "cg_s", nx + 1, ny + 1 )
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
    u.w = w.w;
    u.p = w.p;
    u.s = w.s;
    return u;
}

namespace Impl
{
//! The three sums one iteration needs: gamma = r . z, delta = w . z and
//! rr = r . r (the stopping test).
struct CgSums
{
    double gamma = 0.0, delta = 0.0, rr = 0.0;
};

/*!
  \brief w = A z over the unknowns and, in the same pass, the sums of
  CgSums (a functor: Kokkos 3.4 reduces a struct only through a `volatile`
  join, docs: house style §11).
*/
template <class ExecSpace>
struct CgProducts
{
    using value_type = CgSums;
    UnmanagedView<decltype( NodeStencilSystem<ExecSpace>::a )> a;
    UnmanagedView<decltype( NodeStencilSystem<ExecSpace>::nodes )> nodes;
    CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged> v;

    KOKKOS_INLINE_FUNCTION void operator()( const int m, CgSums& sums ) const
    {
        const int ny1 = static_cast<int>( a.extent( 1 ) );
        const int i = nodes( m ) / ny1, j = nodes( m ) % ny1;
        const double az = stencilRow( a, v.z, i, j );
        v.w( i, j ) = az;
        sums.gamma += v.r( i, j ) * v.z( i, j );
        sums.delta += az * v.z( i, j );
        sums.rr += v.r( i, j ) * v.r( i, j );
    }
    KOKKOS_INLINE_FUNCTION void init( CgSums& sums ) const { sums = CgSums{}; }
    KOKKOS_INLINE_FUNCTION void join( volatile CgSums& into,
                                      const volatile CgSums& from ) const
    {
        into.gamma += from.gamma;
        into.delta += from.delta;
        into.rr += from.rr;
    }
};
} // namespace Impl

/*!
  \brief Solves A x = b over the unknowns by conjugate gradients with the
  Jacobi preconditioner M = diag(A) (A symmetric positive definite), from
  the x given (the previous step's pressure is a good start). Stops at
  |r| <= tolerance |b| or after max_iterations; x off the unknowns is left
  as it is. The iteration is Chronopoulos & Gear's (1989) form of
  preconditioned CG: the same iterates as the textbook form in exact
  arithmetic, with s = A p kept by recurrence so that each iteration is one
  update and one pass that forms w = A z with all three of its sums (two
  kernels, one reduction: on a grid of a few thousand nodes the cost of a
  kernel launch, not the arithmetic, sets the time).
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
    const auto v = unmanaged( w );
    const int ny1 = static_cast<int>( x.extent( 1 ) );
    const auto policy = Kokkos::RangePolicy<ExecSpace>( exec, 0, s.num_nodes );

    // r = b - A x (x copied into z on the unknowns only), z = M^-1 r, and
    // |b|^2. z is read as a neighbour: zero off the unknowns; p = s = 0.
    Kokkos::deep_copy( exec, w.z, 0.0 );
    Kokkos::deep_copy( exec, w.p, 0.0 );
    Kokkos::deep_copy( exec, w.s, 0.0 );
    Kokkos::parallel_for(
        "cg_copy_x", policy, KOKKOS_LAMBDA( const int m ) {
            const int n = nodes( m );
            v.z( n / ny1, n % ny1 ) = xu( n / ny1, n % ny1 );
        } );
    Impl::applyStencil( exec, s, w.z, w.w );
    double bb = 0.0;
    Kokkos::parallel_reduce(
        "cg_start", policy,
        KOKKOS_LAMBDA( const int m, double& acc ) {
            const int n = nodes( m );
            const int i = n / ny1, j = n % ny1;
            v.r( i, j ) = bu( i, j ) - v.w( i, j );
            v.z( i, j ) = v.r( i, j ) / a( i, j, 4 );
            acc += bu( i, j ) * bu( i, j );
        },
        bb );
    const Impl::CgProducts<ExecSpace> products{ a, nodes, v };
    Impl::CgSums sums;
    Kokkos::parallel_reduce( "cg_products", policy, products, sums );

    CgReport report;
    report.tolerance = tolerance;
    report.rhs_norm = Kokkos::Experimental::sqrt( bb );
    report.residual_norm = Kokkos::Experimental::sqrt( sums.rr );
    const double target = tolerance * report.rhs_norm;
    double gamma_old = 1.0, alpha_old = 1.0;
    while ( report.residual_norm > target &&
            report.iterations < max_iterations && sums.gamma > 0.0 )
    {
        const double beta =
            report.iterations == 0 ? 0.0 : sums.gamma / gamma_old;
        const double alpha =
            sums.gamma / ( sums.delta - beta * sums.gamma / alpha_old );
        Kokkos::parallel_for(
            "cg_update", policy, KOKKOS_LAMBDA( const int m ) {
                const int n = nodes( m );
                const int i = n / ny1, j = n % ny1;
                v.p( i, j ) = v.z( i, j ) + beta * v.p( i, j );
                v.s( i, j ) = v.w( i, j ) + beta * v.s( i, j );
                xu( i, j ) += alpha * v.p( i, j );
                v.r( i, j ) -= alpha * v.s( i, j );
                v.z( i, j ) = v.r( i, j ) / a( i, j, 4 );
            } );
        gamma_old = sums.gamma;
        alpha_old = alpha;
        Kokkos::parallel_reduce( "cg_products", policy, products, sums );
        report.residual_norm = Kokkos::Experimental::sqrt( sums.rr );
        ++report.iterations;
    }
    report.converged = report.residual_norm <= target;
    return report;
}

} // namespace mpm

#endif // MPM_STENCIL_CG_HPP
