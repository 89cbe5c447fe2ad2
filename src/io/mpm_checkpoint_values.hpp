#ifndef MPM_CHECKPOINT_VALUES_HPP
#define MPM_CHECKPOINT_VALUES_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_checkpoint.hpp>

#include <limits>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
//! Bounds of a state's values that follow from the case's physics (set by
//! stateBounds, src/setup/mpm_state_bounds.hpp); infinite: none.
struct StateBounds
{
    double max_speed_m_per_s = std::numeric_limits<double>::infinity();
    double max_stress_pa = std::numeric_limits<double>::infinity();
    double max_volume_m3 = std::numeric_limits<double>::infinity();
};

//---------------------------------------------------------------------------//
/*!
  \brief Why the point and node values of a checkpoint are not a state a
  run of config can be in, or "" if they are; each value gets the check its
  case-file counterpart gets:
  - every real value of every array finite;
  - particles/status_p 0 (removed) or 1 (active), as many removed points as
    num_removed; particles/id_p unique;
  - particles/x_p and x0_p of an active point inside the grid;
  - particles/m_p > 0, vol_p and vol0_p in (0, bounds.max_volume_m3],
    eps_p_bar_p >= 0;
  - speeds (particles/v_p, water/v_w_p, grid/v_i, dv_i, water_grid/v_w_i,
    dv_w_i) at most bounds.max_speed_m_per_s, stresses and pore pressures
    (particles/sigma_p, water/p_w_p, p_w_held_p) at most
    bounds.max_stress_pa in magnitude;
  - water/S_p within [S_res, S_sat] of the point's material (S_sat for the
    saturated law), water/n_p in (0, 1), k_rel_p in [0, 1], dS_dp_p and
    inflow_weight_p >= 0;
  - grid/flags_i and water_grid/flags_w_i node flags (0..3), grid/active_i
    node indices, grid_num_active at most the number of nodes.
  Messages name the array and the flat index: "particles/m_p[4]: expected
  a mass > 0 kg, found -1".
*/
std::string stateValueError( const Checkpoint& checkpoint,
                             const CaseConfig& config,
                             const StateBounds& bounds );

//! A number for a message, "%.6g" ("-1e+06", "nan").
std::string valueText( double value );

} // namespace Impl
} // namespace mpm

#endif // MPM_CHECKPOINT_VALUES_HPP
