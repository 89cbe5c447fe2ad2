#ifndef MPM_TEST_INFINITE_SLOPE_HPP
#define MPM_TEST_INFINITE_SLOPE_HPP

// The infinite slope of the factor-of-safety tests (tst_fos_slope.cpp):
// its case text and its closed-form factor of safety.
#include <mpm_test_toml.hpp>

#include <cmath>
#include <string>

namespace mpm_test
{
/*!
  \brief An infinite slope of inclination beta_deg, thickness d_m measured
  normal to the slope, on a rough rigid base. The slope is laid flat on
  the grid's fixed bottom edge, L = 40 m long, and gravity is tilted by
  beta (g sin(beta) along the slope). Only its lowest row of cells is
  Mohr-Coulomb soil (c = 5 kPa, phi = psi = 30 deg, associated so that
  the simple shear of the base row has the Coulomb strength c +
  sigma_n tan(phi): non-associated flow gives Davis' smaller
  c cos(phi), tan(phi*) = sin(phi) in simple shear); the rows above are
  an elastic slab of the same weight and stiffness. The slab keeps the
  base row's lateral strain zero, as in an infinite slope, and its free
  ends cannot collapse: a free vertical end of soil is a 4 m cut, which
  fails long before the infinite slope, and tractions on the ends are
  force controlled (they let the layer spread sideways). The sliding
  mechanism is the base row's: the slope's. With `seepage`, the case is
  saturated, with a water table at the surface and p_w = gamma_w d
  cos(beta) at depth d (slope-parallel seepage), held (the trials of
  `rainslide fos` hold it too); K_w is 1e8 Pa (the pressure is held, so
  the stiffness only sets the time step).
*/
inline std::string infiniteSlopeCase( const bool seepage, const double cell_m,
                                      const double beta_deg = 15.0,
                                      const double d_m = 4.0 )
{
    const double pi = std::acos( -1.0 ), g = 9.81, rho = 2038.74,
                 rho_w = 1000.0, n = 0.3, length = 40.0;
    const double beta = beta_deg * pi / 180.0;
    const double g_n = g * std::cos( beta );
    const std::string n_x = std::to_string( int( ( length + 8.0 ) / cell_m ) );
    const std::string n_y = std::to_string( int( ( d_m + 1.0 ) / cell_m ) );
    std::string text =
        "[case]\nname = \"infinite_slope\"\n" +
        std::string( seepage ? "analysis = \"saturated\"\n[water]\n"
                               "bulk_modulus_pa = 1.0e8\n"
                             : "" ) +
        "[grid]\norigin_m = [-4.0, 0.0]\ncell_size_m = " +
        tomlNumber( cell_m ) + "\ncells = [" + n_x + ", " + n_y + "]\n";
    const std::string common =
        ( seepage ? "solid_density_kg_per_m3 = " +
                        tomlNumber( ( rho - n * rho_w ) / ( 1.0 - n ) ) +
                        "\nporosity = 0.3\npermeability_m2 = 1.0e-12\n"
                  : "density_kg_per_m3 = " + tomlNumber( rho ) + "\n" ) +
        "youngs_modulus_pa = 1.0e8\npoisson_ratio = 0.3\n";
    text += "[[materials]]\nname = \"soil\"\nmodel = \"mohr_coulomb\"\n" +
            common +
            "cohesion_peak_pa = 5.0e3\ncohesion_residual_pa = 5.0e3\n"
            "softening_modulus_pa = 0.0\nfriction_angle_deg = 30.0\n"
            "dilation_angle_deg = 30.0\n";
    text +=
        "[[materials]]\nname = \"slab\"\nmodel = \"linear_elastic\"\n" + common;
    const std::string water =
        seepage
            ? "initial_pore_pressure_pa = " + tomlNumber( rho_w * g_n * d_m ) +
                  "\ninitial_pore_pressure_gradient_pa_per_m = " +
                  tomlNumber( -rho_w * g_n ) + "\n"
            : "";
    const auto body =
        [&]( const char* material, const double y0, const double y1 )
    {
        return std::string( "[[bodies]]\nmaterial = \"" ) + material +
               "\"\npolygon_m = [[0.0, " + tomlNumber( y0 ) + "], [" +
               tomlNumber( length ) + ", " + tomlNumber( y0 ) + "], [" +
               tomlNumber( length ) + ", " + tomlNumber( y1 ) + "], [0.0, " +
               tomlNumber( y1 ) + "]]\n" + water;
    };
    text += body( "soil", 0.0, cell_m ) + body( "slab", cell_m, d_m );
    text += "[[boundaries]]\nwhere = \"bottom\"\ncondition = \"fixed\"\n"
            "[solver]\ncourant_number = 0.9\nbbar = true\n";
    text += "[[stages]]\nname = \"gravity\"\ntype = \"quasi_static\"\n"
            "gravity_m_per_s2 = [" +
            tomlNumber( g * std::sin( beta ) ) + ", " + tomlNumber( -g_n ) +
            "]\ndamping = 0.7\nduration_s = 10.0\n";
    if ( seepage )
        text += "[[stages.pore_pressures]]\nwhere = \"all\"\n"
                "hold = \"initial\"\n";
    return text;
}

/*!
  \brief Closed-form factor of safety of that slope at depth d_m (normal
  to the slope; z = d / cos(beta) vertically): dry,
  c / (gamma z cos(beta) sin(beta)) + tan(phi) / tan(beta); with
  slope-parallel seepage and the water table at the surface,
  c / (gamma_sat z cos(beta) sin(beta)) + (gamma' / gamma_sat) tan(phi) /
  tan(beta).
*/
inline double infiniteSlopeFactor( const bool seepage, const double d_m = 4.0,
                                   const double beta_deg = 15.0 )
{
    const double pi = std::acos( -1.0 ), g = 9.81;
    const double beta = beta_deg * pi / 180.0, phi = 30.0 * pi / 180.0;
    const double gamma = 2038.74 * g, gamma_w = 1000.0 * g, c = 5.0e3;
    const double z = d_m / std::cos( beta );
    const double friction = seepage ? ( gamma - gamma_w ) / gamma : 1.0;
    return c / ( gamma * z * std::cos( beta ) * std::sin( beta ) ) +
           friction * std::tan( phi ) / std::tan( beta );
}

} // namespace mpm_test

#endif // MPM_TEST_INFINITE_SLOPE_HPP
