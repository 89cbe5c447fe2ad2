#include <solver/drivers/mpm_fos_search.hpp>

#include <algorithm>
#include <cmath>

namespace mpm
{
//---------------------------------------------------------------------------//
FosSearchResult
searchFactorOfSafety( const FosSearchSettings& settings,
                      const std::function<FosVerdict( double )>& trial )
{
    FosSearchResult result;
    const auto run = [&]( const double factor )
    {
        const bool fails = trial( factor ).fails;
        result.trial_factors.push_back( factor );
        result.trial_fails.push_back( fails );
        if ( fails )
            result.failing = result.failing > 0.0
                                 ? std::min( result.failing, factor )
                                 : factor;
        else
            result.stable = std::max( result.stable, factor );
        return fails;
    };
    const auto trialsLeft = [&]()
    {
        return static_cast<int>( result.trial_factors.size() ) <
               settings.max_trials;
    };
    const double lo = settings.min_factor, hi = settings.max_factor;
    double factor = std::clamp( settings.start, lo, hi );
    double step = settings.step;

    // Bracketing: up while stable, down while failing.
    const bool first_fails = run( factor );
    while ( trialsLeft() )
    {
        if ( result.stable > 0.0 && result.failing > 0.0 )
            break;
        if ( first_fails )
        {
            if ( factor <= lo )
            {
                result.status = "fails_at_min_factor";
                return result;
            }
            // Halve the distance to the floor rather than cross it.
            factor = factor - step > lo ? factor - step : 0.5 * ( factor + lo );
            if ( factor - lo < settings.tolerance )
                factor = lo;
        }
        else
        {
            if ( factor >= hi )
            {
                result.status = "stable_at_max_factor";
                return result;
            }
            factor = std::min( factor + step, hi );
        }
        step *= 2.0;
        run( factor );
    }

    // Bisection of [stable, failing].
    while ( result.stable > 0.0 && result.failing > 0.0 &&
            result.failing - result.stable > 2.0 * settings.tolerance &&
            trialsLeft() )
        run( 0.5 * ( result.stable + result.failing ) );
    if ( !( result.stable > 0.0 && result.failing > 0.0 ) ||
         result.failing - result.stable > 2.0 * settings.tolerance )
    {
        result.status = "too_many_trials";
        return result;
    }
    result.found = true;
    result.status = "found";
    result.factor = 0.5 * ( result.stable + result.failing );
    return result;
}

} // namespace mpm
