#ifndef MPM_CELL_PRESSURE_SLOPE_HPP
#define MPM_CELL_PRESSURE_SLOPE_HPP

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Slope of a cell's pore pressure along one grid direction, Pa/m,
  from the one-sided differences to its two neighbours along it
  (van Leer's monotonised central limiter):
    s = minmod(2 s_-, 2 s_+, (s_- + s_+) / 2),
  0 where the cell is a local extremum; with one neighbour, its one-sided
  difference; with none, 0.

  The cell equilibrium (CellWaterEquilibrium) gives the points of a cell
  the pressure P + s . (x_p - x_c) instead of one P: a hydrostatic or
  linear field is then exact at every point (a uniform P is wrong by
  rho_w g h / 4 at the points of a hydrostatic cell), while the slope,
  taken from the neighbours and not from the cell's own points, still
  leaves no pressure mode inside a cell, and the limiter makes no new
  extremum at a wetting front.
*/
KOKKOS_INLINE_FUNCTION double limitedPressureSlope( const bool has_minus,
                                                    const double minus,
                                                    const bool has_plus,
                                                    const double plus )
{
    if ( has_minus && has_plus )
    {
        if ( !( minus * plus > 0.0 ) )
            return 0.0;
        const double central = 0.5 * ( minus + plus );
        const double sign = central > 0.0 ? 1.0 : -1.0;
        double magnitude = sign * central;
        magnitude =
            2.0 * sign * minus < magnitude ? 2.0 * sign * minus : magnitude;
        magnitude =
            2.0 * sign * plus < magnitude ? 2.0 * sign * plus : magnitude;
        return sign * magnitude;
    }
    if ( has_minus )
        return minus;
    if ( has_plus )
        return plus;
    return 0.0;
}

} // namespace physics
} // namespace mpm

#endif // MPM_CELL_PRESSURE_SLOPE_HPP
