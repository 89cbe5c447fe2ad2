#include <io/mpm_case_materials.hpp>
#include <io/mpm_case_retention.hpp>

#include <array>
#include <cmath>
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
//! Which analyses use a material parameter.
enum class Phase
{
    Any,
    DryOnly,     //!< bulk density: the two-phase mixture density is derived
    TwoPhaseOnly //!< grain density, porosity, permeability
};

// Material parameters: key, allowed range on its own, unit, model, phase.
struct ParamSpec
{
    const char* key;
    Range range;
    const char* unit;
    bool mohr_coulomb_only;
    Phase phase;
    bool required; //!< for its model and phase
    double MaterialConfig::*member;
};

const std::array<ParamSpec, NumMaterialParams>& paramSpecs()
{
    const Phase any = Phase::Any;
    static const std::array<ParamSpec, NumMaterialParams> specs = { {
        { "density_kg_per_m3", Range::above( 0.0 ), "kg/m^3", false,
          Phase::DryOnly, true, &MaterialConfig::density_kg_per_m3 },
        { "youngs_modulus_pa", Range::above( 0.0 ), "Pa", false, any, true,
          &MaterialConfig::youngs_modulus_pa },
        { "poisson_ratio", Range::interval( 0.0, false, 0.5, true ), "", false,
          any, true, &MaterialConfig::poisson_ratio },
        { "cohesion_peak_pa", Range::atLeast( 0.0 ), "Pa", true, any, true,
          &MaterialConfig::cohesion_peak_pa },
        { "cohesion_residual_pa", Range::atLeast( 0.0 ), "Pa", true, any, false,
          &MaterialConfig::cohesion_residual_pa },
        { "softening_modulus_pa", Range::atMost( 0.0 ), "Pa", true, any, false,
          &MaterialConfig::softening_modulus_pa },
        { "friction_angle_deg", Range::interval( 0.0, true, 90.0, true ),
          "degrees", true, any, true, &MaterialConfig::friction_angle_deg },
        { "dilation_angle_deg", Range::interval( 0.0, false, 90.0, true ),
          "degrees", true, any, false, &MaterialConfig::dilation_angle_deg },
        { "tensile_strength_pa", Range::atLeast( 0.0 ), "Pa", true, any, false,
          &MaterialConfig::tensile_strength_pa },
        { "solid_density_kg_per_m3", Range::above( 0.0 ), "kg/m^3", false,
          Phase::TwoPhaseOnly, true, &MaterialConfig::solid_density_kg_per_m3 },
        { "porosity", Range::interval( 0.0, true, 1.0, true ), "", false,
          Phase::TwoPhaseOnly, true, &MaterialConfig::porosity },
        { "permeability_m2", Range::above( 0.0 ), "m^2 (intrinsic)", false,
          Phase::TwoPhaseOnly, true, &MaterialConfig::permeability_m2 },
    } };
    return specs;
}

//---------------------------------------------------------------------------//
// Whether a parameter is used by the analysis (any, if it is unknown).
bool usedBy( const Phase phase, const Analysis& analysis )
{
    if ( !analysis || phase == Phase::Any )
        return true;
    return ( phase == Phase::TwoPhaseOnly ) == isTwoPhase( analysis );
}

//---------------------------------------------------------------------------//
// Report a parameter given for an analysis that does not use it.
void wrongPhase( const ParamSpec& spec, TableReader& reader )
{
    const std::string text =
        spec.phase == Phase::DryOnly
            ? "not used in two-phase analyses: give solid_density_kg_per_m3 "
              "and porosity (the mixture density follows from them and the "
              "water density)"
            : twoPhaseOnlyText();
    reader.diag().keyError( *reader.find( spec.key ),
                            reader.keyPath( spec.key ), text );
}

//---------------------------------------------------------------------------//
// Why a missing parameter is required, for the message.
std::string missingNote( const ParamSpec& spec, const TableReader& reader )
{
    if ( spec.mohr_coulomb_only )
        return " (required for model mohr_coulomb)";
    if ( spec.phase == Phase::TwoPhaseOnly )
        return " (required for two-phase analyses)";
    if ( spec.phase == Phase::DryOnly )
        for ( const auto& other : paramSpecs() )
            if ( other.phase == Phase::TwoPhaseOnly &&
                 reader.find( other.key ) )
                return " (the bulk density of a dry analysis; for a two-phase "
                       "analysis set case.analysis = \"saturated\" or "
                       "\"unsaturated\")";
    return "";
}

//---------------------------------------------------------------------------//
// Read a retention table given in this table over the draft's law.
void readRetentionTable( TableReader& reader, MaterialDraft& draft,
                         const Analysis& analysis )
{
    const toml::node* node = reader.find( "retention" );
    if ( !node )
        return;
    if ( analysis && *analysis != AnalysisType::Unsaturated )
    {
        reader.diag().keyError(
            *node, reader.keyPath( "retention" ),
            std::string( "only for case.analysis = \"unsaturated\" (a "
                         "soil-water retention law); this case is " ) +
                ( isDry( analysis ) ? "dry" : "saturated (S = 1)" ) );
        return;
    }
    draft.retention_given = true;
    draft.retention.reset();
    if ( const auto* table = reader.subTable( "retention", Need::Optional ) )
        draft.retention = readRetention( *table, reader.keyPath( "retention" ),
                                         reader.diag() );
}

const std::vector<std::string> model_names = { "linear_elastic",
                                               "mohr_coulomb" };
const std::vector<std::string> softening_measure_names = {
    "equivalent_plastic_strain", "engineering_shear_strain" };

//---------------------------------------------------------------------------//
// Read softening_measure given in this table over the draft's value.
void readSofteningMeasure( TableReader& reader, MaterialDraft& draft )
{
    draft.softening_measure_from_here = false;
    const toml::node* node = reader.find( "softening_measure" );
    if ( !node )
        return;
    const auto index = reader.choice( "softening_measure",
                                      softening_measure_names, Need::Optional );
    if ( !index )
    {
        draft.valid = false;
        return;
    }
    draft.softening_measure = static_cast<SofteningMeasureType>( *index );
    draft.softening_measure_node = node;
    draft.softening_measure_path = reader.keyPath( "softening_measure" );
    draft.softening_measure_from_here = true;
}

//---------------------------------------------------------------------------//
// The draft's softening measure on a material of model m.model: a written
// one on a linear elastic material is a mistake, an inherited one dropped.
void applySofteningMeasure( const MaterialDraft& draft, MaterialConfig& m,
                            Diagnostics& diag )
{
    if ( !draft.softening_measure )
        return;
    if ( m.model == ModelType::MohrCoulomb )
        m.softening_measure = *draft.softening_measure;
    else if ( draft.softening_measure_from_here )
        diag.keyError( *draft.softening_measure_node,
                       draft.softening_measure_path,
                       "only for model mohr_coulomb; material '" + m.name +
                           "' has model linear_elastic here (remove the key "
                           "or set model = \"mohr_coulomb\")" );
}

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

//---------------------------------------------------------------------------//
// Check the tension cut-off against the apex of the Mohr-Coulomb surface,
// sigma_t0 <= c0 cot(phi), and report it on the key given in this table.
void checkTensileStrength( const MaterialDraft& draft, const MaterialConfig& m,
                           Diagnostics& diag )
{
    const auto& tensile = draft.params[ParamTensileStrength];
    const auto& peak = draft.params[ParamCohesionPeak];
    const auto& friction = draft.params[ParamFrictionAngle];
    const double phi = m.friction_angle_deg * M_PI / 180.0;
    const double apex = m.cohesion_peak_pa / std::tan( phi );
    const double sigma_t = m.tensile_strength_pa;
    if ( !tensile || !peak || !friction || sigma_t <= apex )
        return;
    const std::string of = " of material '" + m.name + "'";
    if ( tensile->from_here )
        diag.keyError( *tensile->node, tensile->path,
                       "expected a number in [0, " + formatNumber( apex ) +
                           "] Pa (at most the apex c0 cot(phi) = "
                           "cohesion_peak_pa / tan(friction_angle_deg)" +
                           of + "), found " + formatNumber( sigma_t ) );
    else if ( peak->from_here )
        diag.keyError( *peak->node, peak->path,
                       "expected a number >= " +
                           formatNumber( sigma_t * std::tan( phi ) ) +
                           " Pa (so that the apex c0 cot(phi) is at least "
                           "tensile_strength_pa" +
                           of + ", given at " + tensile->path + "), found " +
                           formatNumber( m.cohesion_peak_pa ) );
    else if ( friction->from_here )
        diag.keyError(
            *friction->node, friction->path,
            "expected a number in (0, " +
                formatNumber( std::atan( m.cohesion_peak_pa / sigma_t ) *
                              180.0 / M_PI ) +
                "] degrees (so that the apex c0 cot(phi) is at least "
                "tensile_strength_pa" +
                of + ", given at " + tensile->path + "), found " +
                formatNumber( m.friction_angle_deg ) );
}

} // namespace

//---------------------------------------------------------------------------//
std::vector<std::string> materialKeys()
{
    std::vector<std::string> keys = { "name", "model" };
    for ( const auto& spec : paramSpecs() )
        keys.push_back( spec.key );
    keys.push_back( "softening_measure" );
    keys.push_back( "retention" );
    return keys;
}

//---------------------------------------------------------------------------//
// Read model and parameters given in one table over the draft's values.
void readMaterialValues( TableReader& reader, MaterialDraft& draft,
                         const Need model_need, const Analysis& analysis )
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
        if ( !usedBy( spec.phase, analysis ) )
        {
            if ( reader.find( spec.key ) )
                wrongPhase( spec, reader );
            continue;
        }
        const auto value =
            reader.number( spec.key, spec.range, spec.unit, Need::Optional );
        if ( value )
            draft.params[p] = GivenValue{ *value, reader.find( spec.key ),
                                          reader.keyPath( spec.key ), true };
    }
    readSofteningMeasure( reader, draft );
    readRetentionTable( reader, draft, analysis );
    draft.valid = draft.valid && reader.diag().count() == errors_before;
}

//---------------------------------------------------------------------------//
// The material described by a draft, or nothing after reporting errors.
std::optional<MaterialConfig> finishMaterial( const MaterialDraft& draft,
                                              TableReader& reader,
                                              const Analysis& analysis )
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
        if ( !usedBy( spec.phase, analysis ) )
            continue; // reported when read
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
        else if ( spec.required && ( spec.phase == Phase::Any || analysis ) )
            reader.missing( spec.key,
                            Impl::numberExpectation( spec.range, spec.unit ) +
                                missingNote( spec, reader ) );
    }
    if ( analysis == AnalysisType::Unsaturated && !draft.retention_given )
        reader.missing( "retention",
                        "a table [materials.retention] with the soil-water "
                        "retention law (required for case.analysis = "
                        "\"unsaturated\")" );
    if ( draft.retention )
        m.retention = *draft.retention;
    applySofteningMeasure( draft, m, diag );
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
        checkTensileStrength( draft, m, diag );
    }
    return diag.count() == errors_before ? std::optional<MaterialConfig>( m )
                                         : std::nullopt;
}

} // namespace Impl
} // namespace mpm
