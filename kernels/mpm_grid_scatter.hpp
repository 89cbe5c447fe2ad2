#ifndef MPM_GRID_SCATTER_HPP
#define MPM_GRID_SCATTER_HPP

#include <mpm_device_type.hpp>
#include <mpm_scatter.hpp>

#include <Kokkos_Core.hpp>

#include <string>
#include <type_traits>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Persistent sums of NumFields point contributions per grid entry
  (node or cell), kept between steps so that no step allocates, resets or
  contributes a whole grid.

  A point loop adds into the copy of its thread (ScatterDuplicated: one
  copy per thread, plain adds), into one shared copy (ScatterNonDuplicated:
  atomics, plain adds on Serial), and marks the entries it touches. The
  loop that consumes the sums visits each touched entry once and take()s
  every field: the sum over the copies, which clears them. Only touched
  entries are ever non-zero, so the cost follows the points, not the grid
  (the paper's slope fills a fifth of its grid). The copies add up in the
  order Kokkos' ScatterView contributes them, 0 + copy 0 + copy 1 + ...
  Kernels capture handle(), which does not own the sums.
*/
template <class ExecSpace, int NumFields,
          class Duplication = typename ScatterDuplication<ExecSpace>::type>
class GridScatter
{
  public:
    using execution_space = ExecSpace;
    using device_type = DeviceType<ExecSpace>;
    using sums_view = Kokkos::View<double** [NumFields], device_type>;
    using touched_view = Kokkos::View<int**, device_type>;
    using index_view = Kokkos::View<int*, device_type>;
    using token_type = Kokkos::Experimental::UniqueToken<
        ExecSpace, Kokkos::Experimental::UniqueTokenScope::Global>;
    static constexpr int num_fields = NumFields;
    static constexpr bool duplicated =
        std::is_same<Duplication,
                     Kokkos::Experimental::ScatterDuplicated>::value;
    static constexpr bool atomic =
        std::is_same<ScatterContribution<ExecSpace, Duplication>,
                     Kokkos::Experimental::ScatterAtomic>::value;

    //! The sums as kernels use them (no ownership, cheap to copy).
    class Handle
    {
      public:
        //! The contributions of one thread (RAII copy slot).
        class Access
        {
          public:
            KOKKOS_INLINE_FUNCTION Access( const Handle& handle )
                : _handle( handle )
                , _copy( handle.acquire() )
            {
            }
            KOKKOS_INLINE_FUNCTION ~Access() { _handle.release( _copy ); }

            //! sums(entry, field) += value.
            KOKKOS_INLINE_FUNCTION void add( const int entry, const int field,
                                             const double value ) const
            {
                double& sum = _handle._sums( _copy, entry, field );
                if constexpr ( atomic )
                    Kokkos::atomic_add( &sum, value );
                else
                    sum += value;
            }

            //! Marks an entry as touched (listed by listTouched).
            KOKKOS_INLINE_FUNCTION void touch( const int entry ) const
            {
                int& mark = _handle._touched( _copy, entry );
                if constexpr ( atomic )
                    Kokkos::atomic_assign( &mark, 1 );
                else
                    mark = 1;
            }

          private:
            const Handle& _handle;
            const int _copy;
        };

        Handle( const sums_view& sums, const touched_view& touched )
            : _sums( sums )
            , _touched( touched )
        {
        }

        //! The calling thread's access (inside a point loop).
        KOKKOS_INLINE_FUNCTION Access access() const { return Access( *this ); }

        //! Sum over the copies of `field` at `entry`; clears them. Each
        //! entry and field is taken by one thread.
        KOKKOS_INLINE_FUNCTION double take( const int entry,
                                            const int field ) const
        {
            double sum = 0.0;
            for ( int c = 0; c < static_cast<int>( _sums.extent( 0 ) ); ++c )
            {
                sum += _sums( c, entry, field );
                _sums( c, entry, field ) = 0.0;
            }
            return sum;
        }

      private:
        KOKKOS_INLINE_FUNCTION int acquire() const
        {
            if constexpr ( duplicated )
                return _token.acquire();
            else
                return 0;
        }
        KOKKOS_INLINE_FUNCTION void release( const int copy ) const
        {
            if constexpr ( duplicated )
                _token.release( copy );
            else
                (void)copy;
        }

        UnmanagedView<sums_view> _sums;
        UnmanagedView<touched_view> _touched;
        token_type _token;
    };

    GridScatter() = default;

    //! Zero sums over `num_entries` entries, one copy per thread if
    //! duplicated.
    GridScatter( const std::string& label, const int num_entries )
        : _sums( label, numCopies(), num_entries )
        , _touched( label + "_touched", numCopies(), num_entries )
    {
    }

    //! Number of copies: the threads of ExecSpace if duplicated, else 1.
    static int numCopies() { return duplicated ? token_type().size() : 1; }

    bool allocated() const { return _sums.extent( 0 ) > 0; }

    //! What a kernel captures; valid while this GridScatter lives.
    Handle handle() const { return Handle( _sums, _touched ); }

    /*!
      \brief Lists the touched entries, in increasing order, into `list`
      and clears their marks; returns how many there are.
    */
    int listTouched( const ExecSpace& exec_space, const index_view& list ) const
    {
        const auto touched = unmanaged( _touched );
        const auto entries = unmanaged( list );
        const int num_copies = touched.extent( 0 );
        int count = 0;
        Kokkos::parallel_scan(
            "mpm::list_touched",
            Kokkos::RangePolicy<ExecSpace>( exec_space, 0,
                                            touched.extent( 1 ) ),
            KOKKOS_LAMBDA( const int e, int& offset, const bool final ) {
                int hit = 0;
                for ( int c = 0; c < num_copies; ++c )
                    hit |= touched( c, e );
                if ( !hit )
                    return;
                if ( final )
                {
                    entries( offset ) = e;
                    for ( int c = 0; c < num_copies; ++c )
                        touched( c, e ) = 0;
                }
                ++offset;
            },
            count );
        return count;
    }

  private:
    sums_view _sums;
    touched_view _touched;
};

//---------------------------------------------------------------------------//
//! Flat index i * (ny + 1) + j of node (i, j) (as in GridViews::active_i).
KOKKOS_INLINE_FUNCTION int nodeIndex( const int i, const int j, const int ny1 )
{
    return i * ny1 + j;
}

} // namespace mpm

#endif // MPM_GRID_SCATTER_HPP
