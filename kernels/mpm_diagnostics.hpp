#ifndef MPM_DIAGNOSTICS_HPP
#define MPM_DIAGNOSTICS_HPP

#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief What the last point loop of a step reports about the new state,
  so the time loop needs no reduction of its own: the CFL limit
  (criticalTimeStep / criticalTimeStepTwoPhase), the kinetic energy
  (kineticEnergy) and what findUnstablePoint needs to clear the state.
*/
struct StepDiagnostics
{
    double dt_limit;       //!< min over points of h / (c_p + |v_p|), s
    double max_wave_speed; //!< max over points of c_p, m/s
    double kinetic_energy; //!< sum 0.5 m_p |v_p|^2, J
    double max_speed2;     //!< max |v_p|^2 of the sound points, m^2/s^2
    int first_unsound;     //!< smallest index failing PointSoundness, or
                           //!< the number of points if none
};

//---------------------------------------------------------------------------//
/*!
  \brief Whether point p's position, stress, strain, plastic shear strain,
  volume (two-phase: pore pressure, water velocity) and speed^2 are finite
  and its volume is positive.
*/
template <class ExecSpace>
struct PointSoundness
{
    typename ParticleViews<ExecSpace>::unmanaged_type points;
    typename WaterParticleViews<ExecSpace>::unmanaged_type water_points;
    bool two_phase;

    PointSoundness( const ParticleViews<ExecSpace>& pv,
                    const WaterParticleViews<ExecSpace>& wv )
        : points( unmanaged( pv ) )
        , water_points( unmanaged( wv ) )
        , two_phase( wv.allocated() )
    {
    }

    //! Point p with speed^2 `speed2`.
    KOKKOS_INLINE_FUNCTION bool operator()( const int p,
                                            const double speed2 ) const
    {
        namespace KE = Kokkos::Experimental;
        // Any NaN or infinity makes the sum non-finite.
        const double sum =
            points.x_p( p, 0 ) + points.x_p( p, 1 ) + points.sigma_p( p, 0 ) +
            points.sigma_p( p, 1 ) + points.sigma_p( p, 2 ) +
            points.sigma_p( p, 3 ) + points.eps_p( p, 0 ) +
            points.eps_p( p, 1 ) + points.eps_p( p, 2 ) + points.eps_p( p, 3 ) +
            points.eps_p_bar_p( p ) + points.vol_p( p ) +
            ( two_phase ? water_points.p_w_p( p ) + water_points.v_w_p( p, 0 ) +
                              water_points.v_w_p( p, 1 )
                        : 0.0 );
        return KE::isfinite( sum ) && KE::isfinite( speed2 ) &&
               points.vol_p( p ) > 0.0;
    }
};

//---------------------------------------------------------------------------//
//! Squared length a^2 + b^2 of a 2-vector.
KOKKOS_INLINE_FUNCTION double length2( const double a, const double b )
{
    return a * a + b * b;
}

//! Squared solid speed |v_p|^2 of point p, m^2/s^2.
template <class Points>
KOKKOS_INLINE_FUNCTION double speed2( const Points& points, const int p )
{
    return length2( points.v_p( p, 0 ), points.v_p( p, 1 ) );
}

//---------------------------------------------------------------------------//
/*!
  \brief term(p) over the active points joined by a Kokkos reducer
  (Kokkos::Sum<Value>, Kokkos::Max<Value>, ...): its value_type.
*/
template <class Reducer, class ExecSpace, class Term>
typename Reducer::value_type
reduceOverActivePoints( const ExecSpace& exec_space, const char* label,
                        const ParticleViews<ExecSpace>& pv, const Term& term )
{
    using Value = typename Reducer::value_type;
    const auto points = unmanaged( pv );
    Value result{};
    const Reducer reducer( result );
    Kokkos::parallel_reduce(
        label, Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, Value& joined ) {
            if ( points.status_p( p ) == point_active )
                reducer.join( joined, term( p ) );
        },
        reducer );
    return result;
}

//! Total kinetic energy sum 0.5 m_p |v_p|^2, J (per metre out of plane).
template <class ExecSpace>
double kineticEnergy( const ExecSpace& exec_space,
                      const ParticleViews<ExecSpace>& pv )
{
    const auto points = unmanaged( pv );
    return reduceOverActivePoints<Kokkos::Sum<double>>(
        exec_space, "mpm::kinetic_energy", pv, KOKKOS_LAMBDA( const int p ) {
            return 0.5 * points.m_p( p ) * speed2( points, p );
        } );
}

//---------------------------------------------------------------------------//
//! sqrt of the largest length2(p) over the active points.
template <class ExecSpace, class Length2>
double maxLengthOverActivePoints( const ExecSpace& exec_space,
                                  const char* label,
                                  const ParticleViews<ExecSpace>& pv,
                                  const Length2& length2 )
{
    return Kokkos::Experimental::sqrt(
        reduceOverActivePoints<Kokkos::Max<double>>( exec_space, label, pv,
                                                     length2 ) );
}

//! Largest solid speed |v_p| over the active points, m/s.
template <class ExecSpace>
double maxPointSpeed( const ExecSpace& exec_space,
                      const ParticleViews<ExecSpace>& pv )
{
    const auto points = unmanaged( pv );
    return maxLengthOverActivePoints(
        exec_space, "mpm::max_point_speed", pv,
        KOKKOS_LAMBDA( const int p ) { return speed2( points, p ); } );
}

/*!
  \brief Number of active points whose solid speed |v_p| is not below
  `speed` (|v_p| >= speed, or not a number): the count that decides
  whether a percentile of the speeds is below `speed`, without a sort.
*/
template <class ExecSpace>
long countPointsNotBelowSpeed( const ExecSpace& exec_space,
                               const ParticleViews<ExecSpace>& pv,
                               const double speed )
{
    const auto points = unmanaged( pv );
    const double limit2 = speed * speed;
    return reduceOverActivePoints<Kokkos::Sum<long>>(
        exec_space, "mpm::count_points_not_below_speed", pv,
        KOKKOS_LAMBDA( const int p ) {
            return !( speed2( points, p ) < limit2 ) ? 1L : 0L;
        } );
}

//! Largest displacement |x_p - x0_p| over the active points, m.
template <class ExecSpace>
double maxDisplacement( const ExecSpace& exec_space,
                        const ParticleViews<ExecSpace>& pv )
{
    const auto points = unmanaged( pv );
    return maxLengthOverActivePoints(
        exec_space, "mpm::max_displacement", pv, KOKKOS_LAMBDA( const int p ) {
            return length2( points.x_p( p, 0 ) - points.x0_p( p, 0 ),
                            points.x_p( p, 1 ) - points.x0_p( p, 1 ) );
        } );
}

/*!
  \brief Initial area (vol0_p, m^3 per metre) of the active points that
  have moved more than `displacement` (m) from where they started: the
  size of a mechanism.
*/
template <class ExecSpace>
double movedArea( const ExecSpace& exec_space,
                  const ParticleViews<ExecSpace>& pv,
                  const double displacement )
{
    const auto points = unmanaged( pv );
    const double limit2 = displacement * displacement;
    return reduceOverActivePoints<Kokkos::Sum<double>>(
        exec_space, "mpm::moved_area", pv, KOKKOS_LAMBDA( const int p ) {
            const bool moved =
                length2( points.x_p( p, 0 ) - points.x0_p( p, 0 ),
                         points.x_p( p, 1 ) - points.x0_p( p, 1 ) ) > limit2;
            return moved ? points.vol0_p( p ) : 0.0;
        } );
}

//---------------------------------------------------------------------------//
/*!
  \brief Smallest index of an active point whose position, velocity,
  stress, strain, plastic shear strain, volume (two-phase: pore pressure,
  water velocity) is not finite, or
  whose speed exceeds `speed_limit`; -1 if there is none.
*/
template <class ExecSpace>
int findUnstablePoint( const ExecSpace& exec_space,
                       const ParticleViews<ExecSpace>& pv,
                       const WaterParticleViews<ExecSpace>& wv,
                       const double speed_limit )
{
    const PointSoundness<ExecSpace> sound( pv, wv );
    const auto points = unmanaged( pv );
    const int none = pv.size();
    int first = none;
    Kokkos::parallel_reduce(
        "mpm::find_unstable_point",
        Kokkos::RangePolicy<ExecSpace>( exec_space, 0, pv.size() ),
        KOKKOS_LAMBDA( const int p, int& first_bad ) {
            if ( points.status_p( p ) != point_active )
                return;
            const double speed2 = mpm::speed2( points, p );
            const bool bad =
                !sound( p, speed2 ) || speed2 > speed_limit * speed_limit;
            if ( bad && p < first_bad )
                first_bad = p;
        },
        Kokkos::Min<int>( first ) );
    return first >= none ? -1 : first;
}

} // namespace mpm

#endif // MPM_DIAGNOSTICS_HPP
