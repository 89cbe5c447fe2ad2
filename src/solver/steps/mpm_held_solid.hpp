#ifndef MPM_HELD_SOLID_HPP
#define MPM_HELD_SOLID_HPP

#include <mpm_grid_views.hpp>
#include <mpm_seepage.hpp>

#include <utility>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The solid fixed at every node while it lives: swaps the grid's
  flags with `held`, the same flags with both fixities set (holdSolidFlags),
  and back when it goes, also if the step stops the run. The water's ties
  and every other flag stay.
*/
template <class ExecSpace>
class HeldSolid
{
  public:
    using flag_view = typename GridViews<ExecSpace>::int_view;

    HeldSolid( const ExecSpace& exec, flag_view& flags, flag_view& held )
        : _flags( flags )
        , _held( held )
    {
        holdSolidFlags( exec, _flags, _held );
        std::swap( _flags, _held );
    }
    ~HeldSolid() { std::swap( _flags, _held ); }
    HeldSolid( const HeldSolid& ) = delete;
    HeldSolid& operator=( const HeldSolid& ) = delete;

  private:
    flag_view& _flags;
    flag_view& _held;
};

} // namespace mpm

#endif // MPM_HELD_SOLID_HPP
