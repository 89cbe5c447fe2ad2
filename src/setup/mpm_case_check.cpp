#include <io/mpm_case_reader.hpp>
#include <setup/mpm_case_check.hpp>
#include <setup/mpm_point_check.hpp>

#include <utility>

namespace mpm
{
//---------------------------------------------------------------------------//
CaseCheck checkCase( const std::string& case_file,
                     const std::vector<std::string>& overrides,
                     const RunBudget& budget )
{
    CaseCheck check;
    check.config = readCaseFile( case_file, overrides );
    const CaseConfig& config = check.config;
    // Refuse what cannot finish or exceeds the budget, before any work.
    check.estimate = estimateRun( config );
    check.errors =
        runRefusals( config, check.estimate, budget, check.cannot_finish );
    if ( !check.errors.empty() )
    {
        check.refused_by = CheckRefusal::Estimate;
        return check;
    }
    // Errors that show only once the points exist (as a run makes them).
    double vertices = 0.0;
    for ( const BodyConfig& body : config.bodies )
        vertices += static_cast<double>( body.polygon_m.size() );
    // generatePoints tests the rows of points against every edge, then
    // each point against the bodies.
    const double rows = static_cast<double>( config.grid.cells[1] ) *
                        config.points_per_cell_per_direction;
    if ( check.estimate.points * vertices <= max_point_tests &&
         rows * vertices <= max_point_tests )
    {
        check.points_checked = true;
        PointFindings findings = checkPoints( config );
        check.errors = std::move( findings.refusals );
        check.point_warnings = std::move( findings.warnings );
        if ( !check.errors.empty() )
            check.refused_by = CheckRefusal::Points;
    }
    return check;
}

//---------------------------------------------------------------------------//
std::string checkErrorReport( const CaseCheck& check )
{
    std::string report;
    for ( const std::string& error : check.errors )
        report += check.config.file + ": error: " + error + "\n";
    if ( check.refused_by == CheckRefusal::Estimate )
        report += "  " + estimateSummary( check.estimate ) + "\n";
    return report;
}

} // namespace mpm
