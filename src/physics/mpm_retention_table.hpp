#ifndef MPM_RETENTION_TABLE_HPP
#define MPM_RETENTION_TABLE_HPP

#include <physics/mpm_retention_params.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief A retention law tabulated in the suction s = -p_w: S, dS/dp_w and
  k_rel as cubics in s on intervals of 1/128 of a binade, from 2^-20 Pa to
  2^30 Pa (outside: the exact law).

  The interval and the position t in it come from the bits of s (its
  exponent and the top 7 bits of its mantissa; t the remaining 45), so a
  lookup is two shifts, a multiplication and three Horner cubics instead of
  the four to six exp/log of the van Genuchten law. Each cubic interpolates
  the exact law at t = 0, 1/3, 2/3 and 1 (continuous across intervals); on
  an interval 1/256 to 1/128 as wide as s, its relative error is below
  1e-9 in S, 1e-8 in dS/dp_w and 1.2e-7 in k_rel for laws with 1.2 <= n <=
  6 (tests/tst_retention_table.cpp). k_rel is tabulated without the floor
  k_rel_min, which the lookup applies. 614 kB per law.

  Layout: interval i holds 12 coefficients, c[12 i + 4 q + k] the t^k
  coefficient of quantity q (0: S, 1: dS/dp_w, 2: k_rel).
*/
struct RetentionTable
{
    static constexpr int mantissa_bits = 7;  //!< 128 intervals per binade
    static constexpr int exponent_min = -20; //!< s >= 2^-20 Pa
    static constexpr int exponent_max = 30;  //!< s < 2^30 Pa
    static constexpr int intervals = ( exponent_max - exponent_min )
                                     << mantissa_bits;
    static constexpr int quantities = 3;
    static constexpr int stride = 4 * quantities; //!< doubles per interval
    static constexpr int size = intervals * stride;
    static constexpr int fraction_bits = 52 - mantissa_bits;

    /*!
      \brief The interval of suction s (Pa) and the position t in [0, 1)
      in it; -1 if s lies outside the table (or is not a finite positive
      number).
    */
    KOKKOS_INLINE_FUNCTION static int interval( const double s, double& t )
    {
        std::uint64_t bits;
        std::memcpy( &bits, &s, sizeof bits );
        // Sign, exponent and the top mantissa bits; 2^-20 has biased
        // exponent 1003.
        const std::int64_t first = std::int64_t( exponent_min + 1023 )
                                   << mantissa_bits;
        const std::int64_t index =
            static_cast<std::int64_t>( bits >> fraction_bits ) - first;
        if ( index < 0 || index >= intervals )
            return -1;
        constexpr std::uint64_t fraction_mask =
            ( std::uint64_t( 1 ) << fraction_bits ) - 1;
        constexpr double scale =
            1.0 / double( std::uint64_t( 1 ) << fraction_bits );
        t = static_cast<double>( bits & fraction_mask ) * scale;
        return static_cast<int>( index );
    }

    //! The suction (Pa) at position t of interval i (the table builder).
    static double suction( const int i, const double t )
    {
        const int exponent = exponent_min + ( i >> mantissa_bits );
        const int within = i & ( ( 1 << mantissa_bits ) - 1 );
        return std::ldexp( 1.0 + ( within + t ) / ( 1 << mantissa_bits ),
                           exponent );
    }

    //! Quantity q of the cubic of interval i at t.
    KOKKOS_INLINE_FUNCTION static double
    value( const double* table, const int i, const int q, const double t )
    {
        const double* c = table + i * stride + 4 * q;
        return ( ( c[3] * t + c[2] ) * t + c[1] ) * t + c[0];
    }

    /*!
      \brief The coefficients of the cubic through f0..f3 at t = 0, 1/3,
      2/3, 1 (Newton's forward differences in u = 3 t, expanded).
    */
    static void cubic( const double f[4], double* c )
    {
        const double d1 = f[1] - f[0];
        const double d2 = f[2] - 2.0 * f[1] + f[0];
        const double d3 = f[3] - 3.0 * f[2] + 3.0 * f[1] - f[0];
        c[0] = f[0];
        c[1] = 3.0 * ( d1 - 0.5 * d2 + d3 / 3.0 );
        c[2] = 9.0 * ( 0.5 * d2 - 0.5 * d3 );
        c[3] = 27.0 * ( d3 / 6.0 );
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_RETENTION_TABLE_HPP
