#ifndef MPM_TEST_WATER_HPP
#define MPM_TEST_WATER_HPP

#include <solver/mpm_run_observer.hpp>

namespace mpm_test
{
//! Water volume sum n S V of the points of a snapshot, m^3 per metre.
inline double waterVolume( const mpm::HostSnapshot& snap )
{
    double volume = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
        volume += snap.n[p] * snap.S[p] * snap.vol[p];
    return volume;
}

} // namespace mpm_test

#endif // MPM_TEST_WATER_HPP
