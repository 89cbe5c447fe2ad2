#include <io/mpm_case_materials.hpp>

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
// Material parameters: key, allowed range on its own, unit, model.
struct ParamSpec
{
    const char* key;
    Range range;
    const char* unit;
    bool mohr_coulomb_only;
    double MaterialConfig::*member;
};

const std::array<ParamSpec, NumMaterialParams>& paramSpecs()
{
    static const std::array<ParamSpec, NumMaterialParams> specs = { {
        { "density_kg_per_m3", Range::above( 0.0 ), "kg/m^3", false,
          &MaterialConfig::density_kg_per_m3 },
        { "youngs_modulus_pa", Range::above( 0.0 ), "Pa", false,
          &MaterialConfig::youngs_modulus_pa },
        { "poisson_ratio", Range::interval( 0.0, false, 0.5, true ), "", false,
          &MaterialConfig::poisson_ratio },
        { "cohesion_peak_pa", Range::atLeast( 0.0 ), "Pa", true,
          &MaterialConfig::cohesion_peak_pa },
        { "cohesion_residual_pa", Range::atLeast( 0.0 ), "Pa", true,
          &MaterialConfig::cohesion_residual_pa },
        { "softening_modulus_pa", Range::atMost( 0.0 ), "Pa", true,
          &MaterialConfig::softening_modulus_pa },
        { "friction_angle_deg", Range::interval( 0.0, true, 90.0, true ),
          "degrees", true, &MaterialConfig::friction_angle_deg },
        { "dilation_angle_deg", Range::interval( 0.0, false, 90.0, true ),
          "degrees", true, &MaterialConfig::dilation_angle_deg },
    } };
    return specs;
}

const std::vector<std::string> model_names = { "linear_elastic",
                                               "mohr_coulomb" };

//---------------------------------------------------------------------------//
// Check an upper bound between two parameters (residual <= peak, dilation
// <= friction) and report it on the one given in this table.
void checkOrdered( const MaterialDraft& draft, const MaterialConfig& m,
                   const Param low, const Param high, Diagnostics& diag )
{
    const auto& lo = draft.params[low];
    const auto& hi = draft.params[high];
    const ParamSpec& lo_spec = paramSpecs()[low];
    const ParamSpec& hi_spec = paramSpecs()[high];
    const double lo_value = m.*lo_spec.member, hi_value = m.*hi_spec.member;
    if ( !lo || !hi || lo_value <= hi_value ||
         !( lo->from_here || hi->from_here ) )
        return;
    const std::string unit = lo_spec.unit;
    if ( lo->from_here )
        diag.keyError( *lo->node, lo->path,
                       "expected a number in [0, " + formatNumber( hi_value ) +
                           "] " + unit + " (at most " + hi_spec.key +
                           " of material '" + m.name + "'), found " +
                           formatNumber( lo_value ) );
    else
        diag.keyError( *hi->node, hi->path,
                       "expected a number >= " + formatNumber( lo_value ) +
                           " " + unit + " (at least " + lo_spec.key +
                           " of material '" + m.name + "', given at " +
                           lo->path + "), found " + formatNumber( hi_value ) );
}

} // namespace

//---------------------------------------------------------------------------//
std::vector<std::string> materialKeys()
{
    std::vector<std::string> keys = { "name", "model" };
    for ( const auto& spec : paramSpecs() )
        keys.push_back( spec.key );
    return keys;
}

//---------------------------------------------------------------------------//
// Read model and parameters given in one table over the draft's values.
void readMaterialValues( TableReader& reader, MaterialDraft& draft,
                         const Need model_need )
{
    const std::size_t errors_before = reader.diag().count();
    for ( auto& p : draft.params )
        if ( p )
            p->from_here = false;
    if ( const auto m = reader.choice( "model", model_names, model_need ) )
        draft.model = static_cast<ModelType>( *m );
    else if ( reader.find( "model" ) )
        draft.model.reset();
    for ( int p = 0; p < NumMaterialParams; ++p )
    {
        const ParamSpec& spec = paramSpecs()[p];
        const auto value =
            reader.number( spec.key, spec.range, spec.unit, Need::Optional );
        if ( value )
            draft.params[p] = GivenValue{ *value, reader.find( spec.key ),
                                          reader.keyPath( spec.key ), true };
    }
    draft.valid = draft.valid && reader.diag().count() == errors_before;
}

//---------------------------------------------------------------------------//
// The material described by a draft, or nothing after reporting errors.
std::optional<MaterialConfig> finishMaterial( const MaterialDraft& draft,
                                              TableReader& reader )
{
    if ( !draft.model )
        return std::nullopt;
    Diagnostics& diag = reader.diag();
    const std::size_t errors_before = diag.count();
    MaterialConfig m;
    m.name = draft.name;
    m.model = *draft.model;
    const bool mc = m.model == ModelType::MohrCoulomb;
    for ( int p = 0; p < NumMaterialParams; ++p )
    {
        const ParamSpec& spec = paramSpecs()[p];
        const auto& given = draft.params[p];
        if ( spec.mohr_coulomb_only && !mc )
        {
            // Mohr-Coulomb parameters inherited by a linear elastic stage
            // override are dropped; written ones are a mistake.
            if ( given && given->from_here )
                diag.keyError( *given->node, given->path,
                               "only for model mohr_coulomb; material '" +
                                   m.name +
                                   "' has model linear_elastic here (remove "
                                   "the key or set model = \"mohr_coulomb\")" );
            continue;
        }
        if ( given )
            m.*spec.member = given->value;
        else if ( reader.find( spec.key ) )
            continue; // present but invalid: already reported
        else if ( p <= ParamPoissonRatio || p == ParamCohesionPeak ||
                  p == ParamFrictionAngle )
            reader.missing( spec.key,
                            Impl::numberExpectation( spec.range, spec.unit ) +
                                ( spec.mohr_coulomb_only
                                      ? " (required for model mohr_coulomb)"
                                      : "" ) );
    }
    if ( diag.count() != errors_before || !draft.valid )
        return std::nullopt;

    // Defaults and bounds between parameters.
    if ( mc && !draft.params[ParamCohesionResidual] )
        m.cohesion_residual_pa = m.cohesion_peak_pa;
    if ( mc )
    {
        checkOrdered( draft, m, ParamCohesionResidual, ParamCohesionPeak,
                      diag );
        checkOrdered( draft, m, ParamDilationAngle, ParamFrictionAngle, diag );
    }
    return diag.count() == errors_before ? std::optional<MaterialConfig>( m )
                                         : std::nullopt;
}

} // namespace Impl
} // namespace mpm
