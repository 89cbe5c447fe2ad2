#ifndef MPM_TERZAGHI_ERROR_HPP
#define MPM_TERZAGHI_ERROR_HPP

#include <mpm_terzaghi.hpp>
#include <records/mpm_run_records.hpp>

#include <array>
#include <cmath>
#include <map>

namespace mpm_test
{
//! Relative L2 errors of a Terzaghi pore-pressure snapshot.
struct TerzaghiError
{
    double point; //!< sqrt(sum (p_p - p(z_p))^2 / sum p(z_p)^2) over points
    double cell;  //!< the same over cells: cell mean of p_p against p at
                  //!< the cell's mean depth
};

/*!
  \brief Errors against the series solution; z is the initial depth below
  the drained top y = H, cells are cell_size high.
*/
inline TerzaghiError terzaghiError( const mpm::HostSnapshot& snap,
                                    const double H, const double cell_size,
                                    const double p0, const double Tv )
{
    double point_err2 = 0.0, point_ref2 = 0.0;
    std::map<int, std::array<double, 3>> cells; // sum p, sum z, count
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const double z =
            H - ( snap.x[2 * p + 1] - snap.displacement[2 * p + 1] );
        const double exact = p0 * terzaghiPressureRatio( z, H, Tv );
        point_err2 += ( snap.p_w[p] - exact ) * ( snap.p_w[p] - exact );
        point_ref2 += exact * exact;
        auto& c = cells[static_cast<int>( z / cell_size )];
        c[0] += snap.p_w[p];
        c[1] += z;
        c[2] += 1.0;
    }
    double cell_err2 = 0.0, cell_ref2 = 0.0;
    for ( const auto& [index, c] : cells )
    {
        const double mean_p = c[0] / c[2];
        const double exact = p0 * terzaghiPressureRatio( c[1] / c[2], H, Tv );
        cell_err2 += ( mean_p - exact ) * ( mean_p - exact );
        cell_ref2 += exact * exact;
    }
    return { std::sqrt( point_err2 / point_ref2 ),
             std::sqrt( cell_err2 / cell_ref2 ) };
}

} // namespace mpm_test

#endif // MPM_TERZAGHI_ERROR_HPP
