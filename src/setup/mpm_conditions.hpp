#ifndef MPM_CONDITIONS_HPP
#define MPM_CONDITIONS_HPP

#include <case/mpm_case_config.hpp>

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace mpm
{
//! Piecewise-linear interpolation of (x, value) pairs (x increasing) at x,
//! constant beyond the first and last pair; table must not be empty.
double
interpolatePiecewiseLinear( const std::vector<std::array<double, 2>>& table,
                            double x );

//! Value of a piecewise-linear time function at stage time t (1 if empty).
double evaluateTimeFunction( const TimeFunction& function, double t );

//! Mean of a time function over the stage times [t0, t1], exact (the
//! trapezoids between its pairs); its value at t1 if t1 <= t0.
double meanOfTimeFunction( const TimeFunction& function, double t0, double t1 );

//! Initial p_w of a body's point at height y: the body's profile, or
//! a + b y without one, Pa.
double initialPorePressure( const BodyConfig& body, double y );

/*!
  \brief Each fed cell's share of a polyline selection's water
  (polylineCellShares) with the cells occupied by the active points of x
  (2 per point) and status.
*/
std::map<int, double> polylineSelectionShares( const PointSelection& selection,
                                               const std::vector<double>& x,
                                               const std::vector<int>& status,
                                               const GridConfig& grid );

/*!
  \brief The `count` highest active points of each column of points: the
  points sorted by x, a new column where x jumps by more than a tenth of a
  cell (the columns of a regular fill are h / points_per_cell apart; the
  points of one column have moved far less than that at a stage start).
*/
std::vector<bool> topPointsOfColumns( const std::vector<double>& x,
                                      const std::vector<int>& status,
                                      const double cell_size_m,
                                      const std::size_t count );

/*!
  \brief Which points a selection picks, from their positions x (2 per
  point) and status (only active points are picked). SurfaceCells picks the
  points of every occupied cell whose upper neighbour cell holds no point;
  SurfacePoints the two highest points of each column (topPointsOfColumns);
  the edge kinds the points of the cells along that grid edge; All every
  active point; Polyline the points of the cells that take a share of the
  line (polylineSelectionShares).
*/
std::vector<bool> selectPoints( const PointSelection& selection,
                                const std::vector<double>& x,
                                const std::vector<int>& status,
                                const GridConfig& grid );

//! Horizontal extent of the picked points' cells: the number of grid
//! columns holding a picked point times the cell size, m.
double horizontalExtent( const std::vector<bool>& picked,
                         const std::vector<double>& x, const GridConfig& grid );

//! Water tie flags (NodeFlag bits) of every node, flat index i * (ny + 1) + j:
//! grid edges are impermeable (normal water velocity = solid's) unless a
//! boundary drains them; an impermeable below_polyline boundary or interior
//! wall (polyline) ties both components; a drained wall changes no tie.
std::vector<int>
waterNodeFlags( const GridConfig& grid,
                const std::vector<BoundaryConfig>& boundaries );

} // namespace mpm

#endif // MPM_CONDITIONS_HPP
