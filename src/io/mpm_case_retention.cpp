#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_retention.hpp>
#include <io/mpm_toml_access.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
namespace
{
//---------------------------------------------------------------------------//
// Retention models, in the order of RetentionType after Saturated.
const std::vector<std::string> retention_model_names = {
    "van_genuchten", "liakopoulos", "gardner", "linear" };

//! How a retention model uses a key.
enum class Use
{
    No,
    Optional,
    Required
};

//! A retention parameter: key, own range, unit, member and use by model
//! (in the order of retention_model_names).
struct RetentionParamSpec
{
    const char* key;
    Range range;
    const char* unit;
    double RetentionConfig::*member;
    std::array<Use, 4> use;
};

const std::vector<RetentionParamSpec>& retentionSpecs()
{
    constexpr Use N = Use::No, O = Use::Optional, R = Use::Required;
    static const std::vector<RetentionParamSpec> specs = {
        { "residual_saturation",
          Range::interval( 0.0, false, 1.0, true ),
          "",
          &RetentionConfig::residual_saturation,
          { R, O, R, R } },
        { "saturated_saturation",
          Range::interval( 0.0, true, 1.0, false ),
          "",
          &RetentionConfig::saturated_saturation,
          { O, N, O, O } },
        { "alpha_per_pa",
          Range::above( 0.0 ),
          "per Pa",
          &RetentionConfig::alpha_per_pa,
          { R, N, N, N } },
        { "n", Range::above( 1.0 ), "", &RetentionConfig::n, { R, N, N, N } },
        { "alpha_per_m",
          Range::above( 0.0 ),
          "per m of pressure head",
          &RetentionConfig::alpha_per_m,
          { N, N, R, N } },
        { "suction_range_pa",
          Range::above( 0.0 ),
          "Pa",
          &RetentionConfig::suction_range_pa,
          { N, N, N, R } },
        { "k_rel_min",
          Range::interval( 0.0, false, 1.0, true ),
          "",
          &RetentionConfig::k_rel_min,
          { O, O, O, O } },
    };
    return specs;
}

//---------------------------------------------------------------------------//
// "model \"gardner\"" or "models \"van_genuchten\", \"gardner\"": the
// models that use a key.
std::string modelsUsing( const RetentionParamSpec& spec )
{
    std::vector<std::string> models;
    for ( std::size_t m = 0; m < retention_model_names.size(); ++m )
        if ( spec.use[m] != Use::No )
            models.push_back( retention_model_names[m] );
    return ( models.size() == 1 ? "model " : "models " ) +
           quotedList( models, '"' );
}

} // namespace

//---------------------------------------------------------------------------//
std::vector<std::string> retentionKeys()
{
    std::vector<std::string> keys = { "model" };
    for ( const auto& spec : retentionSpecs() )
        keys.push_back( spec.key );
    return keys;
}

//---------------------------------------------------------------------------//
std::optional<RetentionConfig> readRetention( const toml::table& table,
                                              const std::string& path,
                                              Diagnostics& diag )
{
    const std::size_t errors_before = diag.count();
    TableReader r( table, path, diag );
    r.checkKeys( keysOf( "[materials.retention]" ), "a retention table" );
    const auto model =
        r.choice( "model", retention_model_names, Need::Required );
    RetentionConfig law;
    if ( model )
        law.model = static_cast<RetentionType>( *model + 1 );
    for ( const auto& spec : retentionSpecs() )
    {
        const Use use = model ? spec.use[*model] : Use::Optional;
        if ( use == Use::No && r.find( spec.key ) )
        {
            diag.keyError( *r.find( spec.key ), r.keyPath( spec.key ),
                           "only for retention " + modelsUsing( spec ) +
                               "; this law has model \"" +
                               retention_model_names[*model] +
                               "\" (remove the key or change 'model')" );
            continue;
        }
        const std::string expected = numberExpectation( spec.range, spec.unit );
        if ( use == Use::Required && !r.find( spec.key ) )
        {
            r.missing( spec.key, expected +
                                     " (required for retention model \"" +
                                     retention_model_names[*model] + "\")" );
            continue;
        }
        if ( const auto value =
                 r.number( spec.key, spec.range, spec.unit, Need::Optional ) )
            law.*spec.member = *value;
    }
    if ( diag.count() != errors_before || !model )
        return std::nullopt;

    // The saturation range must not be empty.
    if ( const toml::node* s_sat = r.find( "saturated_saturation" ) )
        if ( !( law.saturated_saturation > law.residual_saturation ) )
            diag.mismatch( *s_sat, r.keyPath( "saturated_saturation" ),
                           "a number in (" +
                               formatNumber( law.residual_saturation ) +
                               ", 1] (above residual_saturation)" );
    return diag.count() == errors_before ? std::optional<RetentionConfig>( law )
                                         : std::nullopt;
}

} // namespace Impl
} // namespace mpm
