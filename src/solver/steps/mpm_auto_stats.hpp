#ifndef MPM_AUTO_STATS_HPP
#define MPM_AUTO_STATS_HPP

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace mpm
{
//! A change of the auto scheme from one scheme to the other.
struct SchemeSwitch
{
    double time_s = 0.0; //!< simulated time of the switch
    std::string to;      //!< the scheme it switched to
    std::string reason;
};

//! The steps the auto scheme took with one of its schemes.
struct SchemeSteps
{
    long steps = 0;
    double wall_s = 0.0; //!< including the steps tried and given up
    double min_step_s = std::numeric_limits<double>::infinity();
    double max_step_s = 0.0;

    //! A step its rule chose (`chosen`, before any cut to land on an
    //! output time).
    void add( const double chosen )
    {
        ++steps;
        min_step_s = std::min( min_step_s, chosen );
        max_step_s = std::max( max_step_s, chosen );
    }
};

//! What the auto scheme did (metrics.json's `auto`).
struct AutoStats
{
    std::vector<SchemeSwitch> switches;
    SchemeSteps quasi_static, dynamic;
};

} // namespace mpm

#endif // MPM_AUTO_STATS_HPP
