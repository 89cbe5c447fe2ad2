#ifndef MPM_TERZAGHI_HPP
#define MPM_TERZAGHI_HPP

#include <cmath>

namespace mpm_test
{
//! Terzaghi's series solution p / p0 at depth z below the drained face of
//! a layer of drainage length H, time factor Tv (verification.md 2.1).
inline double terzaghiPressureRatio( const double z, const double H,
                                     const double Tv )
{
    double sum = 0.0;
    for ( int m = 0; m < 200; ++m )
    {
        const double M = 0.5 * M_PI * ( 2 * m + 1 );
        sum += 2.0 / M * std::sin( M * z / H ) * std::exp( -M * M * Tv );
    }
    return sum;
}

//! Degree of consolidation U(Tv).
inline double terzaghiDegree( const double Tv )
{
    double sum = 0.0;
    for ( int m = 0; m < 200; ++m )
    {
        const double M = 0.5 * M_PI * ( 2 * m + 1 );
        sum += 2.0 / ( M * M ) * std::exp( -M * M * Tv );
    }
    return 1.0 - sum;
}

} // namespace mpm_test

#endif // MPM_TERZAGHI_HPP
