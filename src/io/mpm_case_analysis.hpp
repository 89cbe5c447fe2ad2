#ifndef MPM_CASE_ANALYSIS_HPP
#define MPM_CASE_ANALYSIS_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_toml_access.hpp>

#include <optional>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// The analysis type (case.analysis) as seen by the checks of the other
// tables: which keys are allowed or required. Internal to the case reader.
//---------------------------------------------------------------------------//

//! The analysis of the case being read; empty when case.analysis is invalid
//! (then the checks that depend on it are skipped, to avoid follow-on
//! errors).
using Analysis = std::optional<AnalysisType>;

//! \brief The values of case.analysis, in the order of AnalysisType.
inline const std::vector<std::string>& analysisNames()
{
    static const std::vector<std::string> names = { "dry", "saturated",
                                                    "unsaturated" };
    return names;
}

inline bool isDry( const Analysis& analysis )
{
    return analysis && *analysis == AnalysisType::Dry;
}

inline bool isTwoPhase( const Analysis& analysis )
{
    return analysis && *analysis != AnalysisType::Dry;
}

//! \brief Message for a two-phase key given in a dry case.
inline std::string twoPhaseOnlyText()
{
    return "only for two-phase analyses (case.analysis = \"saturated\" or "
           "\"unsaturated\"); this case is dry";
}

//! \brief Report key if it is given in a dry case; whether it was.
inline bool rejectIfDry( TableReader& reader, const std::string& key,
                         const Analysis& analysis )
{
    const toml::node* node = reader.find( key );
    if ( !node || !isDry( analysis ) )
        return false;
    reader.diag().keyError( *node, reader.keyPath( key ), twoPhaseOnlyText() );
    return true;
}

/*!
  \brief Reads the required table [case] of `root` (name, description,
  analysis) into `config` and returns the analysis: "dry" if [case] or its
  key is left out, nothing if the key is invalid or misspelt (the checks
  that depend on it are then skipped).
*/
Analysis readCaseTable( TableReader& root, Diagnostics& diag,
                        CaseConfig& config );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_ANALYSIS_HPP
