#ifndef MPM_CASE_MATERIALS_HPP
#define MPM_CASE_MATERIALS_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_analysis.hpp>
#include <io/mpm_toml_access.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// [[materials]] tables and their stage overrides [stages.materials.<name>].
// Internal to the case reader.
//---------------------------------------------------------------------------//

//! Material parameters, in the order of the keys in a case file.
enum Param
{
    ParamDensity,
    ParamYoungsModulus,
    ParamPoissonRatio,
    ParamCohesionPeak,
    ParamCohesionResidual,
    ParamSofteningModulus,
    ParamFrictionAngle,
    ParamDilationAngle,
    ParamTensileStrength,
    ParamSolidDensity,
    ParamPorosity,
    ParamPermeability,
    NumMaterialParams
};

//---------------------------------------------------------------------------//
// A material as written, remembering where each value was given, so that a
// stage override can be checked against the values it inherits.
struct GivenValue
{
    double value;
    const toml::node* node;
    std::string path;
    bool from_here; //!< given in the table being checked
};

struct MaterialDraft
{
    std::string name;
    std::optional<ModelType> model;
    //! softening_measure, when given at some level (inherited like a
    //! parameter: the node and path of where it was given, from_here).
    std::optional<SofteningMeasureType> softening_measure;
    const toml::node* softening_measure_node = nullptr;
    std::string softening_measure_path;
    bool softening_measure_from_here = false;
    std::array<std::optional<GivenValue>, NumMaterialParams>
        params; //!< by Param
    //! The retention law (unsaturated analyses): given at some level,
    //! and its value if it was valid. A stage override replaces it whole.
    bool retention_given = false;
    std::optional<RetentionConfig> retention;
    bool valid = true; //!< false once a value had a wrong type or range
};

//---------------------------------------------------------------------------//
//! \brief Every key allowed in a [[materials]] table.
std::vector<std::string> materialKeys();

//---------------------------------------------------------------------------//
/*!
  \brief Read the model and the parameters given in one table over the
  draft's values (checking each value's type and own range, and that the
  key is used by the analysis). Values already in the draft are marked as
  inherited. A retention table replaces the draft's law.
*/
void readMaterialValues( TableReader& reader, MaterialDraft& draft,
                         Need model_need, const Analysis& analysis );

//---------------------------------------------------------------------------//
/*!
  \brief The material described by a draft, with defaults applied, after
  checking required keys (by model and analysis), keys only for
  mohr_coulomb and residual <= peak, dilation <= friction, tensile strength
  <= c0 cot(phi); or nothing after
  reporting errors to the reader.
*/
std::optional<MaterialConfig> finishMaterial( const MaterialDraft& draft,
                                              TableReader& reader,
                                              const Analysis& analysis );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_MATERIALS_HPP
