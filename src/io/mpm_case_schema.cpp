#include <io/mpm_case_schema.hpp>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
const std::vector<std::string>& twoPhaseSchemeNames()
{
    static const std::vector<std::string> names = {
        "explicit", "semi_implicit", "seepage", "quasi_static", "auto" };
    return names;
}

//---------------------------------------------------------------------------//
const std::vector<ConfigKey<SolverConfig>>& solverKeys()
{
    using S = SolverConfig;
    static const std::vector<ConfigKey<S>> keys = {
        numberKey( "courant_number", &S::courant_number,
                   Range::interval( 0.0, true, 1.0, false ), "" ),
        numberKey( "dt_s", &S::dt_s, Range::atLeast( 0.0 ),
                   "s (0 = automatic)" ),
        numberKey( "flip_fraction", &S::flip_fraction,
                   Range::interval( 0.0, false, 1.0, false ), "" ),
        flagKey( "bbar", &S::bbar ),
        flagKey( "moduli_fall_with_dilation", &S::moduli_fall_with_dilation ),
        flagKey( "base_cell_completion", &S::base_cell_completion ),
        flagKey( "cell_equilibrium", &S::cell_equilibrium ),
        flagKey( "cell_pressure_slope", &S::cell_pressure_slope ),
        flagKey( "retention_table", &S::retention_table ),
        flagKey( "water_relative_flip", &S::water_relative_flip ),
        flagKey( "remove_points_leaving_grid", &S::remove_points_leaving_grid ),
        numberKey( "instability_speed_factor", &S::instability_speed_factor,
                   Range::above( 0.0 ), "" ),
        numberKey( "inertia_scaling", &S::inertia_scaling,
                   Range::atLeast( 1.0 ), "(inertial mass factor)" ),
        numberKey( "checkpoint_interval_s", &S::checkpoint_interval_s,
                   Range::atLeast( 0.0 ),
                   "s of simulated time (0 = no checkpoints)" ),
        choiceKey<S, TwoPhaseScheme, &S::scheme>( "scheme",
                                                  twoPhaseSchemeNames() ),
        numberKey( "seepage_saturation_change", &S::seepage_saturation_change,
                   Range::interval( 0.0, true, 1.0, false ), "" ),
        numberKey( "seepage_initial_dt_s", &S::seepage_initial_dt_s,
                   Range::above( 0.0 ), "s" ),
        numberKey( "relaxation_speed_m_per_s", &S::relaxation_speed_m_per_s,
                   Range::above( 0.0 ), "m/s" ),
        numberKey( "relaxation_max_steps", &S::relaxation_max_steps,
                   Range::interval( 1.0, false, 1.0e6, false ), "" ),
        numberKey( "relaxation_damping", &S::relaxation_damping,
                   Range::interval( 0.0, false, 1.0, true ), "" ),
        numberKey( "auto_rest_speed_m_per_s", &S::auto_rest_speed_m_per_s,
                   Range::above( 0.0 ), "m/s" ),
        numberKey( "auto_rest_window_s", &S::auto_rest_window_s,
                   Range::atLeast( 0.0 ), "s" ),
        numberKey( "pressure_tolerance", &S::pressure_tolerance,
                   Range::interval( 0.0, true, 1.0, true ),
                   "(relative residual)" ),
        numberKey( "pressure_max_iterations", &S::pressure_max_iterations,
                   Range::interval( 1.0, false, 1.0e6, false ), "" ),
        numberKey( "pressure_picard_tolerance", &S::pressure_picard_tolerance,
                   Range::interval( 0.0, true, 1.0, true ),
                   "(relative water residual)" ) };
    return keys;
}

//---------------------------------------------------------------------------//
const std::vector<ConfigKey<WaterConfig>>& waterKeys()
{
    using W = WaterConfig;
    static const std::vector<ConfigKey<W>> keys = {
        numberKey( "density_kg_per_m3", &W::density_kg_per_m3,
                   Range::above( 0.0 ), "kg/m^3" ),
        numberKey( "bulk_modulus_pa", &W::bulk_modulus_pa, Range::above( 0.0 ),
                   "Pa" ),
        numberKey( "viscosity_pa_s", &W::viscosity_pa_s, Range::above( 0.0 ),
                   "Pa s" ) };
    return keys;
}

} // namespace Impl
} // namespace mpm
