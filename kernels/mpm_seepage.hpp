#ifndef MPM_SEEPAGE_HPP
#define MPM_SEEPAGE_HPP

#include <mpm_grid_views.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_status_flags.hpp>
#include <mpm_water_views.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

//---------------------------------------------------------------------------//
// The seepage step's own kernels (SeepageStep): the solid held at the nodes,
// and the saturation change that sets the next step.
//---------------------------------------------------------------------------//

namespace mpm
{
//---------------------------------------------------------------------------//
//! held_i = flags_i with the solid fixed along x and y at every node (the
//! water's ties and every other flag kept): the seepage step's grid.
template <class ExecSpace, class FlagView>
void holdSolidFlags( const ExecSpace& exec, const FlagView& flags_i,
                     const FlagView& held_i )
{
    const auto flags = unmanaged( flags_i );
    const auto held = unmanaged( held_i );
    const int ny1 = static_cast<int>( flags_i.extent( 1 ) );
    Kokkos::parallel_for(
        "mpm::hold_solid_flags",
        Kokkos::RangePolicy<ExecSpace>(
            exec, 0, static_cast<int>( flags_i.extent( 0 ) ) * ny1 ),
        KOKKOS_LAMBDA( const int n ) {
            const int i = n / ny1, j = n % ny1;
            held( i, j ) = flags( i, j ) | node_fix_x | node_fix_y;
        } );
}

//---------------------------------------------------------------------------//
//! The largest |S_p - S_before_p| over the active points whose p_w is free:
//! how far the step's flow moved a point's saturation (a prescribed p_w sets
//! S whatever the step).
template <class ExecSpace, class ScalarView>
double maxSaturationChange( const ExecSpace& exec,
                            const ParticleViews<ExecSpace>& pv,
                            const WaterParticleViews<ExecSpace>& wv,
                            const ScalarView& S_before_p )
{
    const auto status = unmanaged( pv.status_p );
    const auto condition = unmanaged( wv.p_w_condition_p );
    const auto S = unmanaged( wv.S_p );
    const auto before = unmanaged( S_before_p );
    double largest = 0.0;
    Kokkos::parallel_reduce(
        "mpm::max_saturation_change",
        Kokkos::RangePolicy<ExecSpace>( exec, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, double& change ) {
            if ( status( p ) != point_active || condition( p ) >= 0 )
                return;
            const double d = Kokkos::Experimental::fabs( S( p ) - before( p ) );
            change = d > change ? d : change;
        },
        Kokkos::Max<double>( largest ) );
    return largest > 0.0 ? largest : 0.0; // no free point: no change
}

} // namespace mpm

#endif // MPM_SEEPAGE_HPP
