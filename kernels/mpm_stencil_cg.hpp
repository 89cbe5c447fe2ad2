#ifndef MPM_STENCIL_CG_HPP
#define MPM_STENCIL_CG_HPP

//---------------------------------------------------------------------------//
// The pressure solve of a semi-implicit step: the system of
// mpm_stencil_system.hpp solved by preconditioned conjugate gradients (block
// DILU or Jacobi) in one team kernel over the list of unknown nodes.
//---------------------------------------------------------------------------//

#include <mpm_device_type.hpp>
#include <mpm_stencil_system.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace mpm
{
namespace Impl
{
//! Three sums over the unknowns: in an iteration gamma = r . z,
//! delta = w . z and rr = r . r (the stopping test).
struct CgSums
{
    double gamma = 0.0, delta = 0.0, rr = 0.0;
};

//! Flags of an unknown's row (CgWorkspace::rows).
constexpr int row_interior = 1;
constexpr int row_in_block = 2;

/*!
  \brief solveStencilCg in one kernel launch: one team whose threads share
  the unknowns, each a contiguous range of whole DILU blocks (the same in
  every phase, so a thread preconditions the residual it updated). They
  meet at a barrier wherever one reads what another wrote (z at the
  neighbours in A z; the sums), and each adds the iteration's sums from
  the threads' partials in the same order, so all take the same alpha, beta
  and stopping decision. One launch per solve instead of two per iteration
  and five to start: a 6-iteration solve on 1,089 unknowns took 72 us on 2
  threads against 131 us with a kernel per phase (docs/formulation.md §9).
  The phases work on raw pointers (flat node indices, the work vectors in
  the unknowns' order), which the compiler keeps in registers.
*/
template <class ExecSpace, class NodeView>
struct TeamCg
{
    using member_type = typename Kokkos::TeamPolicy<ExecSpace>::member_type;
    UnmanagedView<decltype( NodeStencilSystem<ExecSpace>::a )> a;
    UnmanagedView<decltype( NodeStencilSystem<ExecSpace>::nodes )> nodes;
    CgWorkspace<ExecSpace, Kokkos::MemoryUnmanaged> v;
    UnmanagedView<NodeView> b, x;
    int num_nodes = 0;
    double tolerance = 0.0;
    int max_iterations = 0;
    CgPreconditioner preconditioner = CgPreconditioner::BlockDilu;
    CgStart start = CgStart::Given;

    //! The sums of every thread's `mine`, the same on all of them.
    KOKKOS_INLINE_FUNCTION CgSums teamSums( const member_type& team,
                                            const CgSums& mine,
                                            int& buffer ) const
    {
        const int first = buffer * team.team_size();
        v.partial( first + team.team_rank(), 0 ) = mine.gamma;
        v.partial( first + team.team_rank(), 1 ) = mine.delta;
        v.partial( first + team.team_rank(), 2 ) = mine.rr;
        team.team_barrier();
        CgSums all;
        for ( int t = first; t < first + team.team_size(); ++t )
        {
            all.gamma += v.partial( t, 0 );
            all.delta += v.partial( t, 1 );
            all.rr += v.partial( t, 2 );
        }
        // The next sums go to the other buffer: a thread may still read
        // this one, but not after the next barrier.
        buffer = 1 - buffer;
        return all;
    }

    //! The first unknown of DILU block k (k = cg_blocks: the end).
    KOKKOS_INLINE_FUNCTION int blockBegin( const int k ) const
    {
        return static_cast<int>( static_cast<long>( k ) * num_nodes /
                                 cg_blocks );
    }

    //! This thread's blocks [first, last).
    KOKKOS_INLINE_FUNCTION void myBlocks( const member_type& team, int& first,
                                          int& last ) const
    {
        first = team.team_rank() * cg_blocks / team.team_size();
        last = ( team.team_rank() + 1 ) * cg_blocks / team.team_size();
    }

    //! f(m) for this thread's share of the unknowns: its blocks' range.
    template <class F>
    KOKKOS_INLINE_FUNCTION void forMyNodes( const member_type& team,
                                            const F& f ) const
    {
        int first, last;
        myBlocks( team, first, last );
        const int end = blockBegin( last );
        for ( int m = blockBegin( first ); m < end; ++m )
            f( m );
    }

    /*!
      \brief f(slot, neighbour) for the neighbours of unknown m (flat node
      n, `interior`: all 8 inside the grid) at the stencil's slots
      [first, last) (0-3: the lower ones, 5-8: the upper ones) that are
      unknowns of [begin, end).
    */
    template <class F>
    KOKKOS_INLINE_FUNCTION void
    forBlockNeighbours( const int n, const bool interior, const int first,
                        const int last, const int begin, const int end,
                        const int nx1, const int ny1, const F& f ) const
    {
        const int* const index = v.unknown_of.data();
        const int i = n / ny1, j = n % ny1;
        for ( int slot = first; slot < last; ++slot )
        {
            const int di = slot / 3 - 1, dj = slot % 3 - 1;
            if ( !interior && ( i + di < 0 || i + di >= nx1 || j + dj < 0 ||
                                j + dj >= ny1 ) )
                continue;
            const int neighbour = n + di * ny1 + dj;
            const int k = index[neighbour];
            if ( k >= begin && k < end )
                f( slot, neighbour );
        }
    }

    //! The DILU pivots of this thread's blocks (their inverses into the
    //! work vector), and which of their rows lie in their block.
    KOKKOS_INLINE_FUNCTION void factor( const member_type& team, const int nx1,
                                        const int ny1 ) const
    {
        const double* const A = a.data();
        int* const N = v.rows.data();
        double* const D = v.inverse_pivot.data();
        const int* const index = v.unknown_of.data();
        int first, last;
        myBlocks( team, first, last );
        for ( int k = first; k < last; ++k )
        {
            const int begin = blockBegin( k ), end = blockBegin( k + 1 );
            for ( int m = begin; m < end; ++m )
            {
                const int n = N[2 * m];
                const bool interior = N[2 * m + 1] & row_interior;
                const double diagonal = A[9 * n + 4];
                double pivot = diagonal;
                forBlockNeighbours( n, interior, 0, 4, begin, end, nx1, ny1,
                                    [&]( const int slot, const int neighbour )
                                    {
                                        pivot -= A[9 * n + slot] *
                                                 A[9 * neighbour + 8 - slot] *
                                                 D[index[neighbour]];
                                    } );
                D[m] = 1.0 /
                       ( pivot >= cg_min_pivot * diagonal ? pivot : diagonal );
                // In its block if no unknown neighbour lies outside it.
                int outside = 0;
                for ( int slot = 0; interior && slot < 9; ++slot )
                {
                    const int j =
                        index[n + ( slot / 3 - 1 ) * ny1 + slot % 3 - 1];
                    outside += j >= 0 && ( j < begin || j >= end );
                }
                if ( interior && outside == 0 )
                    N[2 * m + 1] = row_interior | row_in_block;
            }
        }
    }

    //! z = M^-1 r on this thread's blocks (a forward and a backward sweep
    //! through each). A row in its block reads its neighbours unchecked (z
    //! is 0 off the unknowns).
    KOKKOS_INLINE_FUNCTION void
    precondition( const member_type& team, const int nx1, const int ny1 ) const
    {
        const double* const A = a.data();
        const int* const N = v.rows.data();
        const double* const R = v.r.data();
        const double* const D = v.inverse_pivot.data();
        double* const Z = v.z.data();
        int first, last;
        myBlocks( team, first, last );
        for ( int k = first; k < last; ++k )
        {
            const int begin = blockBegin( k ), end = blockBegin( k + 1 );
            // (P + L) y = r, y into z. A row in its block takes its lower
            // neighbour in the column, (i, j - 1), from the last row if that
            // is it (else it is no unknown: 0), so that the sweep's chain of
            // dependent rows runs through registers, not memory.
            double last_y = 0.0;
            for ( int m = begin; m < end; ++m )
            {
                const int n = N[2 * m];
                const double* const c = A + 9 * n;
                if ( N[2 * m + 1] & row_in_block )
                {
                    const double below =
                        m > begin && N[2 * ( m - 1 )] == n - 1 ? last_y : 0.0;
                    const double rest =
                        R[m] - ( ( c[0] * Z[n - ny1 - 1] + c[1] * Z[n - ny1] ) +
                                 c[2] * Z[n - ny1 + 1] );
                    last_y = rest * D[m] - ( c[3] * D[m] ) * below;
                }
                else
                {
                    double sum = R[m];
                    forBlockNeighbours(
                        n, N[2 * m + 1] & row_interior, 0, 4, begin, end, nx1,
                        ny1,
                        [&]( const int slot, const int neighbour )
                        { sum -= c[slot] * Z[neighbour]; } );
                    last_y = sum * D[m];
                }
                Z[n] = last_y;
            }
            // (P + L^T) z = P y, the same way upwards: (i, j + 1).
            double last_z = 0.0;
            for ( int m = end - 1; m >= begin; --m )
            {
                const int n = N[2 * m];
                const double* const c = A + 9 * n;
                if ( N[2 * m + 1] & row_in_block )
                {
                    const double above =
                        m + 1 < end && N[2 * ( m + 1 )] == n + 1 ? last_z : 0.0;
                    const double rest =
                        ( c[6] * Z[n + ny1 - 1] + c[7] * Z[n + ny1] ) +
                        c[8] * Z[n + ny1 + 1];
                    last_z = ( Z[n] - rest * D[m] ) - ( c[5] * D[m] ) * above;
                }
                else
                {
                    double sum = 0.0;
                    forBlockNeighbours(
                        n, N[2 * m + 1] & row_interior, 5, 9, begin, end, nx1,
                        ny1,
                        [&]( const int slot, const int neighbour )
                        { sum += c[slot] * Z[neighbour]; } );
                    last_z = Z[n] - sum * D[m];
                }
                Z[n] = last_z;
            }
        }
    }

    KOKKOS_INLINE_FUNCTION void operator()( const member_type& team ) const
    {
        const int nx1 = static_cast<int>( a.extent( 0 ) );
        const int ny1 = static_cast<int>( a.extent( 1 ) );
        const bool jacobi = preconditioner == CgPreconditioner::Jacobi;
        const double* const A = a.data();
        const double* const B = b.data();
        double* const X = x.data();
        double* const Z = v.z.data();
        double* const R = v.r.data();
        double* const W = v.w.data();
        double* const P = v.p.data();
        double* const S = v.s.data();
        double* const D = v.inverse_pivot.data();
        int* const index = v.unknown_of.data();
        int* const N = v.rows.data(); // N[2 m]: flat index, N[2 m + 1]: flags
        // A z at unknown m (its flat index n).
        const auto row = [=]( const int m, const int n )
        {
            return ( N[2 * m + 1] & row_interior )
                       ? interiorRow( A, Z, n, ny1 )
                       : edgeRow( A, Z, n, nx1, ny1 );
        };
        const bool zero_start = start == CgStart::Zero;
        int buffer = 0;
        // z = 0 off the unknowns (read as a neighbour) and no index: every
        // node is so but the last solve's unknowns.
        Kokkos::parallel_for(
            Kokkos::TeamThreadRange( team, static_cast<int>( v.result( 4 ) ) ),
            [=]( const int m )
            {
                Z[N[2 * m]] = 0.0;
                index[N[2 * m]] = -1;
            } );
        team.team_barrier();
        // z = x on the unknowns; their rows and indices; p = s = 0.
        forMyNodes( team,
                    [=]( const int m )
                    {
                        const int n = nodes( m );
                        N[2 * m] = n;
                        N[2 * m + 1] = isInteriorNode( n, nx1, ny1 );
                        index[n] = m;
                        if ( zero_start )
                            X[n] = 0.0;
                        Z[n] = X[n];
                        P[m] = 0.0;
                        S[m] = 0.0;
                    } );
        team.team_barrier();
        // r = b - A x and |b|^2; the pivots; then z = M^-1 r (after every
        // thread has read its neighbours' z = x).
        double bb_mine = 0.0;
        forMyNodes( team,
                    [&]( const int m )
                    {
                        const int n = N[2 * m];
                        R[m] = B[n] - row( m, n );
                        bb_mine += B[n] * B[n];
                    } );
        if ( jacobi )
            forMyNodes( team, [=]( const int m )
                        { D[m] = 1.0 / A[9 * N[2 * m] + 4]; } );
        else
            factor( team, nx1, ny1 );
        const double bb =
            teamSums( team, CgSums{ 0.0, 0.0, bb_mine }, buffer ).rr;
        const auto preconditionResidual = [&]()
        {
            if ( jacobi )
                forMyNodes( team,
                            [=]( const int m ) { Z[N[2 * m]] = R[m] * D[m]; } );
            else
                precondition( team, nx1, ny1 );
        };
        preconditionResidual();
        team.team_barrier();
        // w = A z and this thread's share of the sums.
        const auto products = [&]()
        {
            double gamma = 0.0, delta = 0.0, rr = 0.0;
            forMyNodes( team,
                        [&]( const int m )
                        {
                            const int n = N[2 * m];
                            const double az = row( m, n );
                            W[m] = az;
                            gamma += R[m] * Z[n];
                            delta += az * Z[n];
                            rr += R[m] * R[m];
                        } );
            return CgSums{ gamma, delta, rr };
        };
        CgSums sums = teamSums( team, products(), buffer );

        const double target = tolerance * Kokkos::Experimental::sqrt( bb );
        double gamma_old = 1.0, alpha_old = 1.0;
        int iterations = 0;
        while ( Kokkos::Experimental::sqrt( sums.rr ) > target &&
                iterations < max_iterations && sums.gamma > 0.0 )
        {
            const double beta = iterations == 0 ? 0.0 : sums.gamma / gamma_old;
            const double alpha =
                sums.gamma / ( sums.delta - beta * sums.gamma / alpha_old );
            forMyNodes( team,
                        [=]( const int m )
                        {
                            const int n = N[2 * m];
                            P[m] = Z[n] + beta * P[m];
                            S[m] = W[m] + beta * S[m];
                            X[n] += alpha * P[m];
                            R[m] -= alpha * S[m];
                        } );
            preconditionResidual();
            team.team_barrier();
            gamma_old = sums.gamma;
            alpha_old = alpha;
            sums = teamSums( team, products(), buffer );
            ++iterations;
        }
        if ( team.team_rank() == 0 )
        {
            v.result( 0 ) = iterations;
            v.result( 1 ) = sums.rr;
            v.result( 2 ) = bb;
            v.result( 3 ) = Kokkos::Experimental::sqrt( sums.rr ) <= target;
            v.result( 4 ) = num_nodes;
        }
    }
};
} // namespace Impl

/*!
  \brief Solves A x = b over the unknowns by conjugate gradients with the
  preconditioner `preconditioner` (CgPreconditioner; A symmetric positive
  definite), from the x given (the previous step's pressure is a good
  start) or, with CgStart::Zero, from x = 0. Stops at |r| <= tolerance |b| or
  after max_iterations; x off the unknowns is left as it is. The iteration is
  Chronopoulos & Gear's (1989) form of preconditioned CG: the same iterates as
  the textbook form in exact arithmetic, with s = A p kept by recurrence so that
  each iteration is one update and one pass that forms w = A z with all three of
  its sums. The whole solve is one kernel launch (Impl::TeamCg: one team of up
  to ExecSpace's concurrency threads).
*/
template <class ExecSpace, class NodeView>
CgReport solveStencilCg(
    const ExecSpace& exec, const NodeStencilSystem<ExecSpace>& s,
    const NodeView& b, const NodeView& x, CgWorkspace<ExecSpace>& w,
    const double tolerance, const int max_iterations,
    const CgPreconditioner preconditioner = CgPreconditioner::BlockDilu,
    const CgStart start = CgStart::Given )
{
    // TeamCg reads b and x by flat node index.
    static_assert( std::is_same<typename NodeView::array_layout,
                                Kokkos::LayoutRight>::value,
                   "solveStencilCg: b and x must be LayoutRight node views" );
    using Solve = Impl::TeamCg<ExecSpace, NodeView>;
    const Solve solve{ unmanaged( s.a ), unmanaged( s.nodes ),
                       unmanaged( w ),   unmanaged( b ),
                       unmanaged( x ),   s.num_nodes,
                       tolerance,        max_iterations,
                       preconditioner,   start };
    const Kokkos::TeamPolicy<ExecSpace> probe( exec, 1, 1 );
    // As many threads as `partial` has rows in each of its two buffers.
    const int threads =
        std::min( static_cast<int>( w.partial.extent( 0 ) ) / 2,
                  probe.team_size_max( solve, Kokkos::ParallelForTag() ) );
    Kokkos::parallel_for(
        "cg_solve", Kokkos::TeamPolicy<ExecSpace>( exec, 1, threads ), solve );
    exec.fence();
    const auto host =
        Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), w.result );
    CgReport report;
    report.tolerance = tolerance;
    report.iterations = static_cast<int>( host( 0 ) );
    report.residual_norm = std::sqrt( host( 1 ) );
    report.rhs_norm = std::sqrt( host( 2 ) );
    report.converged = host( 3 ) != 0.0;
    return report;
}

} // namespace mpm

#endif // MPM_STENCIL_CG_HPP
