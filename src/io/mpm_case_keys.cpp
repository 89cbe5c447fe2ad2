#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_materials.hpp>
#include <io/mpm_case_retention.hpp>
#include <io/mpm_case_schema.hpp>

#include <stdexcept>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
const std::vector<CaseTableKeys>& caseTableKeys()
{
    static const std::vector<CaseTableKeys> tables = {
        { "[case]", { "name", "description", "analysis" } },
        { "[water]", keyNames( waterKeys() ) },
        { "[grid]", { "origin_m", "cell_size_m", "cells" } },
        { "[particles]", { "points_per_cell" } },
        { "[[materials]]", materialKeys() },
        { "[materials.retention]", retentionKeys() },
        { "[[bodies]]",
          { "material", "polygon_m", "initial_pore_pressure_pa",
            "initial_pore_pressure_gradient_pa_per_m",
            "initial_pore_pressure_profile" } },
        { "[[boundaries]]",
          { "where", "condition", "hydraulic", "polyline_m" } },
        { "[solver]", keyNames( solverKeys() ) },
        { "[[stages]]",
          { "name", "type", "gravity_m_per_s2", "damping", "duration_s",
            "ke_ratio_tolerance", "snapshot_interval_s", "snapshot_times_s",
            "static_stop", "reset_displacement", "initial_stress_k0",
            "materials", "boundaries", "pore_pressures", "loads", "inflows" } },
        { "[stages.static_stop]",
          { "static_speed_m_per_s", "slide_displacement_m", "window_s",
            "speed_percentile" } },
        { "[[stages.pore_pressures]]",
          { "where", "box_m", "pressure_pa", "hold", "time_function" } },
        { "[[stages.loads]]",
          { "where", "box_m", "traction_pa", "length_m", "time_function" } },
        { "[[stages.inflows]]",
          { "where", "box_m", "polyline_m", "measured_on", "flux_m_per_s",
            "length_m", "time_function", "hyetograph_mm_per_h", "ponding",
            "follow_surface_s" } },
        { "[probes]", { "interval_s", "points" } } };
    return tables;
}

//---------------------------------------------------------------------------//
const std::vector<std::string>& keysOf( const std::string& table )
{
    for ( const CaseTableKeys& t : caseTableKeys() )
        if ( t.table == table )
            return t.keys;
    throw std::logic_error( "no declared keys for the case table " + table );
}

} // namespace Impl
} // namespace mpm
