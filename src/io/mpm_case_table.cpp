#include <io/mpm_case_analysis.hpp>
#include <io/mpm_case_diagnostics.hpp>
#include <io/mpm_case_keys.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
Analysis readCaseTable( TableReader& root, Diagnostics& diag,
                        CaseConfig& config )
{
    Analysis analysis = AnalysisType::Dry; // the default
    const auto* t = root.subTable( "case", Need::Required );
    if ( !t )
        return analysis;
    TableReader r( *t, "case", diag );
    checkTableKeys( r, "[case]" );
    if ( const auto name = r.string( "name", Need::Required ) )
    {
        const bool valid =
            std::all_of( name->begin(), name->end(), isBareKeyCharacter );
        if ( !valid )
            diag.mismatch( *r.find( "name" ), "case.name",
                           "a name of letters, digits, '_' and '-' "
                           "(it names the output folder)" );
        config.name = *name;
    }
    config.description =
        r.string( "description", Need::Optional, true ).value_or( "" );
    if ( const auto a =
             r.choice( "analysis", analysisNames(), Need::Optional ) )
        analysis = static_cast<AnalysisType>( *a );
    else if ( r.find( "analysis" ) )
        analysis.reset(); // invalid: skip the checks that depend on it
    else
        for ( auto&& entry : *t )
            if ( closestWord( std::string( entry.first.str() ),
                              keysOf( "[case]" ) ) == "analysis" )
                analysis.reset(); // misspelt key: as invalid
    config.analysis = analysis.value_or( AnalysisType::Dry );
    return analysis;
}

} // namespace Impl
} // namespace mpm
