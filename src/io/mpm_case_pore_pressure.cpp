#include <io/mpm_case_pore_pressure.hpp>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
const char* const profile_key = "initial_pore_pressure_profile";

//---------------------------------------------------------------------------//
// initial_pore_pressure_profile = [[y_m, p_w_pa], ...]: at least two
// pairs of finite numbers, y strictly increasing; empty after an error.
std::vector<std::array<double, 2>> readProfile( TableReader& r )
{
    const std::string expected =
        "an array of 2 to " + std::to_string( max_list_points ) +
        " pairs [[y_m, p_w_pa], ...] (heights in m, strictly increasing, "
        "and pore pressures in Pa)";
    const toml::node& node = *r.find( profile_key );
    const std::string path = r.keyPath( profile_key );
    const toml::array* arr = node.as_array();
    if ( !arr || arr->size() < 2 || arr->size() > max_list_points )
    {
        r.diag().mismatch( node, path, expected );
        return {};
    }
    std::vector<std::array<double, 2>> profile;
    for ( std::size_t k = 0; k < arr->size(); ++k )
    {
        const std::string at = path + "[" + std::to_string( k ) + "]";
        const toml::node& pair_node = *arr->get( k );
        const toml::array* pair = pair_node.as_array();
        if ( !pair || pair->size() != 2 )
        {
            r.diag().mismatch( pair_node, at, "a pair [y_m, p_w_pa]" );
            return {};
        }
        const auto y = readNumber( *pair->get( 0 ), at + "[0]", Range::any(),
                                   "m", r.diag() );
        const auto p = readNumber( *pair->get( 1 ), at + "[1]", Range::any(),
                                   "Pa", r.diag() );
        if ( !y || !p )
            return {};
        if ( !profile.empty() && !( *y > profile.back()[0] ) )
        {
            r.diag().keyError( *pair->get( 0 ), at + "[0]",
                               "expected a height > " +
                                   formatNumber( profile.back()[0] ) +
                                   " m (the heights of a profile must "
                                   "increase strictly), found " +
                                   formatNumber( *y ) + " m" );
            return {};
        }
        profile.push_back( { *y, *p } );
    }
    return profile;
}

} // namespace

//---------------------------------------------------------------------------//
void readInitialPorePressure( TableReader& r, const Analysis& analysis,
                              BodyConfig& body )
{
    const char* const level_key = "initial_pore_pressure_pa";
    const char* const gradient_key = "initial_pore_pressure_gradient_pa_per_m";
    if ( !rejectIfDry( r, profile_key, analysis ) && r.find( profile_key ) )
    {
        for ( const char* key : { level_key, gradient_key } )
            if ( const toml::node* node = r.find( key ) )
                r.diag().keyError(
                    *node, r.keyPath( key ),
                    std::string( "not allowed with " ) + profile_key +
                        ": give either the profile or p_w = a + b y "
                        "(initial_pore_pressure_pa, "
                        "initial_pore_pressure_gradient_pa_per_m)" );
        body.initial_pore_pressure_profile = readProfile( r );
        return;
    }
    if ( !rejectIfDry( r, level_key, analysis ) )
        body.initial_pore_pressure_pa =
            r.number( level_key, Range::any(), "Pa (p_w at y = 0)",
                      Need::Optional )
                .value_or( 0.0 );
    if ( !rejectIfDry( r, gradient_key, analysis ) )
        body.initial_pore_pressure_gradient_pa_per_m =
            r.number( gradient_key, Range::any(), "Pa/m (dp_w/dy)",
                      Need::Optional )
                .value_or( 0.0 );
}

} // namespace Impl
} // namespace mpm
