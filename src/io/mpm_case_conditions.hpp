#ifndef MPM_CASE_CONDITIONS_HPP
#define MPM_CASE_CONDITIONS_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_analysis.hpp>
#include <io/mpm_case_diagnostics.hpp>

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Boundary conditions on grid nodes ([[boundaries]], [[stages.boundaries]])
// and the conditions of a stage on material points ([[stages.pore_pressures]],
// [[stages.loads]], [[stages.inflows]]). Internal to the case reader.
//---------------------------------------------------------------------------//

/*!
  \brief Read an array of boundary tables at prefix ("boundaries" or
  "stages[k].boundaries"), including the hydraulic condition of two-phase
  analyses and purely hydraulic boundaries (condition = "none"). With a
  grid (null if [grid] is invalid), the vertices of an interior wall (where =
  "polyline") are checked against it and points of a below_polyline line
  outside it are warned about.
*/
std::vector<BoundaryConfig> readBoundaries( const toml::array& array,
                                            const std::string& prefix,
                                            const Analysis& analysis,
                                            const GridConfig* grid,
                                            Diagnostics& diag );

//---------------------------------------------------------------------------//
//! \brief Read [[stages.pore_pressures]] tables at prefix.
std::vector<PorePressureCondition> readPorePressures( const toml::array& array,
                                                      const std::string& prefix,
                                                      Diagnostics& diag );

//---------------------------------------------------------------------------//
//! \brief Read [[stages.loads]] tables at prefix.
std::vector<PointLoad> readLoads( const toml::array& array,
                                  const std::string& prefix,
                                  Diagnostics& diag );

/*!
  \brief [[stages.inflows]]: prescribed water inflow (rainfall) on points,
  a grid edge or a polyline (mpm_case_inflows.cpp); with a grid, polyline
  points outside it are warned about.
*/
std::vector<WaterInflow> readInflows( const toml::array& array,
                                      const std::string& prefix,
                                      const GridConfig* grid,
                                      Diagnostics& diag );

//! where (and box_m) of a condition on material points; "polyline" only
//! if polyline_allowed (its polyline_m is read by the caller).
PointSelection readSelection( TableReader& r, bool polyline_allowed );

//! time_function = [[t_s, factor], ...]: optional, empty if not given.
TimeFunction readTimeFunction( TableReader& r );

//! `key` = [[t_s, value], ...], times strictly increasing, each value in
//! `values` (in `unit`): optional, empty if not given.
TimeFunction readTimeFunction( TableReader& r, const char* key,
                               const Range& values, const char* unit );

//! [stages.static_stop] at path: end a dynamic stage once static again (an
//! error for a quasi-static stage).
StaticStop readStaticStop( const toml::table& table, const std::string& path,
                           bool quasi_static, Diagnostics& diag );

//! stages[k].snapshot_times_s: strictly increasing stage times (s) > 0.
std::vector<double> readSnapshotTimes( TableReader& r );

/*!
  \brief The time and motion keys of a stage table `r` at `path` (gravity,
  damping, duration, kinetic-energy tolerance, static stop, snapshots,
  displacement reset) into `stage`, whose type is read (`type_known`:
  without errors).
*/
void readStageTiming( TableReader& r, const std::string& path, bool type_known,
                      StageConfig& stage, Diagnostics& diag );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_CONDITIONS_HPP
