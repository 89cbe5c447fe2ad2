#ifndef MPM_TEST_TOML_HPP
#define MPM_TEST_TOML_HPP

// Pieces of case-file text: each returns whole lines (ending in '\n'),
// its values written as given (TOML text), so that a case is the same text
// wherever it is put together.
#include <cstdio>
#include <string>

namespace mpm_test
{
//! A double with all 17 significant digits (printf's %.17g).
inline std::string tomlNumber( const double value )
{
    char text[32];
    std::snprintf( text, sizeof text, "%.17g", value );
    return text;
}

//! `key = "value"`.
inline std::string tomlString( const std::string& key,
                               const std::string& value )
{
    return key + " = \"" + value + "\"\n";
}

//! [case] named `name`, of `analysis` unless that is empty.
inline std::string caseToml( const std::string& name,
                             const std::string& analysis = "" )
{
    return "[case]\n" + tomlString( "name", name ) +
           ( analysis.empty() ? "" : tomlString( "analysis", analysis ) );
}

//! [grid] from the origin with cells of `cell_size_m` and `cells` "[nx, ny]".
inline std::string gridToml( const std::string& cell_size_m,
                             const std::string& cells )
{
    return "[grid]\norigin_m = [0.0, 0.0]\ncell_size_m = " + cell_size_m +
           "\ncells = " + cells + "\n";
}

//! A dry [[materials]] entry: name, model, density, E (Pa) and nu.
inline std::string dryMaterialToml( const std::string& name,
                                    const std::string& model,
                                    const std::string& density,
                                    const std::string& youngs_modulus,
                                    const std::string& poisson_ratio )
{
    return "[[materials]]\n" + tomlString( "name", name ) +
           tomlString( "model", model ) + "density_kg_per_m3 = " + density +
           "\nyoungs_modulus_pa = " + youngs_modulus +
           "\npoisson_ratio = " + poisson_ratio + "\n";
}

//! A two-phase linear elastic [[materials]] entry "soil" of porosity 0.3:
//! rho_s (kg/m^3), k (m^2), E (Pa) and nu.
inline std::string twoPhaseSoilToml( const std::string& solid_density,
                                     const std::string& permeability,
                                     const std::string& youngs_modulus,
                                     const std::string& poisson_ratio )
{
    return "[[materials]]\nname = \"soil\"\nmodel = \"linear_elastic\"\n"
           "solid_density_kg_per_m3 = " +
           solid_density +
           "\nporosity = 0.3\npermeability_m2 = " + permeability +
           "\nyoungs_modulus_pa = " + youngs_modulus +
           "\npoisson_ratio = " + poisson_ratio + "\n";
}

//! The paper's van Genuchten law as [materials.retention].
inline std::string paperRetentionToml()
{
    return "[materials.retention]\nmodel = \"van_genuchten\"\n"
           "alpha_per_pa = 4.4e-4\nn = 3.04\nresidual_saturation = 0.23\n";
}

//! [[bodies]] of material "soil" with the polygon `polygon_m`.
inline std::string soilBodyToml( const std::string& polygon_m )
{
    return "[[bodies]]\nmaterial = \"soil\"\npolygon_m = " + polygon_m + "\n";
}

//! The rectangle [0, width] x [0, height] as polygon_m text.
inline std::string rectangleToml( const std::string& width,
                                  const std::string& height )
{
    return "[[0.0, 0.0], [" + width + ", 0.0], [" + width + ", " + height +
           "], [0.0, " + height + "]]";
}

//! [[boundaries]] with `condition` on `where`.
inline std::string boundaryToml( const std::string& where,
                                 const std::string& condition )
{
    return "[[boundaries]]\n" + tomlString( "where", where ) +
           tomlString( "condition", condition );
}

//! Rollers (fix_x) on the grid's left and right edges.
inline std::string rollersToml()
{
    return boundaryToml( "left", "fix_x" ) + boundaryToml( "right", "fix_x" );
}

//! A fixed boundary below the polyline `polyline_m`.
inline std::string fixedBelowToml( const std::string& polyline_m )
{
    return boundaryToml( "below_polyline", "fixed" ) +
           "polyline_m = " + polyline_m + "\n";
}

//! [[stages]] `name` of `type` ("dynamic", "quasi_static"), `duration_s`.
inline std::string stageToml( const std::string& name, const std::string& type,
                              const std::string& duration_s )
{
    return "[[stages]]\n" + tomlString( "name", name ) +
           tomlString( "type", type ) + "duration_s = " + duration_s + "\n";
}

//! [[stages.pore_pressures]] holding `pressure_pa` in the box `box_m`.
inline std::string heldBoxToml( const std::string& box_m,
                                const std::string& pressure_pa )
{
    return "[[stages.pore_pressures]]\nwhere = \"box\"\nbox_m = " + box_m +
           "\npressure_pa = " + pressure_pa + "\n";
}

//! [[stages.inflows]] of `flux_m_per_s` on the polyline `polyline_m`.
inline std::string polylineInflowToml( const std::string& polyline_m,
                                       const std::string& flux_m_per_s )
{
    return "[[stages.inflows]]\nwhere = \"polyline\"\npolyline_m = " +
           polyline_m + "\nflux_m_per_s = " + flux_m_per_s + "\n";
}

} // namespace mpm_test

#endif // MPM_TEST_TOML_HPP
