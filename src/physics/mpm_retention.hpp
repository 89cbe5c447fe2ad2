#ifndef MPM_RETENTION_HPP
#define MPM_RETENTION_HPP

#include <physics/mpm_retention_params.hpp>
#include <physics/mpm_retention_table.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
//! Degree of saturation, its derivative dS/dp_w (1/Pa, >= 0) and k_rel.
struct RetentionState
{
    double S;
    double dS_dp;
    double k_rel;
};

//! Degree of saturation and dS/dp_w (1/Pa) only: what the pore-pressure
//! Newton iteration needs.
struct SaturationState
{
    double S;
    double dS_dp;
};

//---------------------------------------------------------------------------//
/*!
  \brief Soil-water retention S(p_w) and relative permeability k_rel(S).

  p_w in Pa, compression positive; suction s = max(-p_w, 0). Every law gives
  S = s_sat (Saturated: 1), dS/dp_w = 0 and k_rel = 1 at p_w >= 0, and
  dS/dp_w >= 0 (S grows as p_w rises to 0; the paper's lambda = -dS/dp_w).
  k_rel is floored at k_rel_min except for the laws with k_rel = 1.
  Pure arithmetic, no loops: callable from any backend.
*/
struct Retention
{
    /*!
      \brief S (-), dS/dp_w (1/Pa) and k_rel (-) at pore pressure p_w (Pa).
      Inline only the table's cubics (the step's hot path: every point,
      every Newton iteration); any other law or suction through law().
    */
    KOKKOS_FORCEINLINE_FUNCTION RetentionState
    operator()( const RetentionParams& r, const double p_w ) const
    {
        RetentionState state;
        return tableState( r, p_w, state ) ? state : law( r, p_w );
    }

    //! The exact law (a table's fallback outside its range, see tableState).
    KOKKOS_INLINE_FUNCTION RetentionState law( const RetentionParams& r,
                                               const double p_w ) const
    {
        switch ( r.model )
        {
        case RetentionModel::VanGenuchten:
            return vanGenuchten( r, p_w );
        case RetentionModel::Liakopoulos:
            return liakopoulos( r, p_w );
        case RetentionModel::Gardner:
            return gardner( r, p_w );
        case RetentionModel::Linear:
            return linear( r, p_w );
        default:
            return RetentionState{ 1.0, 0.0, 1.0 };
        }
    }

    /*!
      \brief S (-) and dS/dp_w (1/Pa) at p_w (Pa), the same values as
      operator() without the cost of k_rel (van Genuchten: an expm1 and a
      sqrt; Liakopoulos: an exp).
    */
    KOKKOS_FORCEINLINE_FUNCTION SaturationState
    saturationState( const RetentionParams& r, const double p_w ) const
    {
        // Inlined, the unused k_rel cubic is dropped.
        RetentionState state;
        if ( tableState( r, p_w, state ) )
            return SaturationState{ state.S, state.dS_dp };
        return lawSaturation( r, p_w );
    }

    //! saturationState of the exact law (as law()).
    KOKKOS_INLINE_FUNCTION SaturationState
    lawSaturation( const RetentionParams& r, const double p_w ) const
    {
        switch ( r.model )
        {
        case RetentionModel::VanGenuchten:
            return vanGenuchtenSaturation( r, p_w ).state;
        case RetentionModel::Liakopoulos:
            return liakopoulosSaturation( r, p_w ).state;
        case RetentionModel::Gardner:
        {
            const RetentionState g = gardner( r, p_w );
            return SaturationState{ g.S, g.dS_dp };
        }
        case RetentionModel::Linear:
        {
            const RetentionState l = linear( r, p_w );
            return SaturationState{ l.S, l.dS_dp };
        }
        default:
            return SaturationState{ 1.0, 0.0 };
        }
    }

    //! \brief Degree of saturation S(p_w) (-) only, p_w in Pa.
    KOKKOS_INLINE_FUNCTION double saturation( const RetentionParams& r,
                                              const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        const double s = p_w < 0.0 ? -p_w : 0.0;
        const double width = r.s_sat - r.s_res;
        switch ( r.model )
        {
        case RetentionModel::VanGenuchten:
        {
            if ( r.table )
                return tabulated( r, p_w ).S;
            // Eq. 16a: S_e = (1 + (alpha s)^n)^-(1 - 1/n).
            const double x = r.alpha_per_pa * s;
            if ( !( x > 0.0 ) )
                return r.s_sat;
            const double m = 1.0 - 1.0 / r.n_vg;
            return r.s_res +
                   width * KE::exp( -m * vanGenuchtenTerms( r.n_vg, x ).log_a );
        }
        case RetentionModel::Liakopoulos:
            return liakopoulos( r, p_w ).S;
        case RetentionModel::Gardner:
            return gardner( r, p_w ).S;
        case RetentionModel::Linear:
            return linear( r, p_w ).S;
        default:
            return 1.0;
        }
    }

    /*!
      \brief Relative permeability k_rel(S) (-) from the degree of saturation.

      van Genuchten: Mualem, Eq. 19, with S_e from Eq. 17 clamped to [0, 1].
      Near S_e = 1 this loses accuracy to the cancellation in S_e = (S -
      s_res) / width; operator() evaluates k_rel from p_w without it.
    */
    KOKKOS_INLINE_FUNCTION double
    relativePermeability( const RetentionParams& r, const double S ) const
    {
        namespace KE = Kokkos::Experimental;
        const double width = r.s_sat - r.s_res;
        double s_e = width > 0.0 ? ( S - r.s_res ) / width : 1.0;
        s_e = s_e < 0.0 ? 0.0 : ( s_e > 1.0 ? 1.0 : s_e );
        double k_rel = 1.0;
        switch ( r.model )
        {
        case RetentionModel::VanGenuchten:
        {
            if ( s_e >= 1.0 )
                return 1.0;
            if ( !( s_e > 0.0 ) )
                return r.k_rel_min;
            // w = S_e^(1/m); log(1 - w) and 1 - (1 - w)^m without cancellation.
            const double m = 1.0 - 1.0 / r.n_vg;
            const double log_w = KE::log( s_e ) / m;
            const double log_u = log_w < -0.6931471805599453
                                     ? KE::log1p( -KE::exp( log_w ) )
                                     : KE::log( -KE::expm1( log_w ) );
            const double t = -KE::expm1( m * log_u );
            k_rel = KE::sqrt( s_e ) * t * t;
            break;
        }
        case RetentionModel::Liakopoulos:
            // Eq. 13: k_rel = 1 - 2.207 (1 - S)^1.0121.
            k_rel = S >= 1.0 ? 1.0 : 1.0 - 2.207 * KE::pow( 1.0 - S, 1.0121 );
            break;
        case RetentionModel::Gardner:
            k_rel = s_e;
            break;
        default:
            return 1.0;
        }
        return k_rel > r.k_rel_min ? k_rel : r.k_rel_min;
    }

    /*!
      \brief van Genuchten, Eqs. 16-17, and Mualem k_rel, Eq. 19; alpha in 1/Pa.

      With x = alpha s, x^n, A = 1 + x^n and m = 1 - 1/n: S_e = A^-m,
      S_e^(1/m) = 1/A, so 1 - S_e^(1/m) = x^n / A exactly and
        k_rel = sqrt(S_e) (1 - (x^n / A)^m)^2,
        dS/dp_w = (s_sat - s_res) (n - 1) S_e (x^n / A) / s.
      log(A) and d = -log(x^n / A) = log1p(1 / x^n) are both formed without
      cancellation; 1 - exp(-m d) uses expm1, so k_rel is accurate at both
      ends (S_e -> 1 and S_e -> 0).
    */
    KOKKOS_INLINE_FUNCTION RetentionState
    vanGenuchten( const RetentionParams& r, const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        const VanGenuchtenSaturation v = vanGenuchtenSaturation( r, p_w );
        if ( v.saturated )
            return RetentionState{ r.s_sat, 0.0, 1.0 };
        const double t = -KE::expm1( -v.m * v.d );
        const double k_rel = KE::sqrt( v.s_e ) * t * t;
        return RetentionState{ v.state.S, v.state.dS_dp,
                               k_rel > r.k_rel_min ? k_rel : r.k_rel_min };
    }

    /*!
      \brief S, dS/dp_w and k_rel of a tabulated law (r.table,
      RetentionTable) at p_w (Pa); the exact law outside the table.
    */
    KOKKOS_INLINE_FUNCTION RetentionState tabulated( const RetentionParams& r,
                                                     const double p_w ) const
    {
        RetentionState state;
        return tableState( r, p_w, state ) ? state : vanGenuchten( r, p_w );
    }

    /*!
      \brief The tabulated van Genuchten law at p_w into `state`: saturated
      (p_w >= 0, as vanGenuchten: S = s_sat, dS/dp_w = 0, k_rel = 1) or
      the table's cubics, k_rel floored at k_rel_min. False (state
      untouched) if r has no table or the suction lies outside it.
    */
    KOKKOS_FORCEINLINE_FUNCTION static bool
    tableState( const RetentionParams& r, const double p_w,
                RetentionState& state )
    {
        if ( r.model != RetentionModel::VanGenuchten || !r.table )
            return false;
        if ( !( p_w < 0.0 ) )
        {
            state = RetentionState{ r.s_sat, 0.0, 1.0 };
            return true;
        }
        double t;
        const int i = RetentionTable::interval( -p_w, t );
        if ( i < 0 )
            return false;
        const double k_rel = RetentionTable::value( r.table, i, 2, t );
        state = RetentionState{ RetentionTable::value( r.table, i, 0, t ),
                                RetentionTable::value( r.table, i, 1, t ),
                                k_rel > r.k_rel_min ? k_rel : r.k_rel_min };
        return true;
    }

    //! S and dS/dp_w of van Genuchten and the terms k_rel needs.
    struct VanGenuchtenSaturation
    {
        SaturationState state;
        bool saturated; //!< s = 0: S = s_sat, k_rel = 1
        double s_e;     //!< effective saturation
        double m;       //!< 1 - 1/n
        double d;       //!< VanGenuchtenTerms::d
    };

    //! \brief S, dS/dp_w and the k_rel terms of vanGenuchten at p_w (Pa).
    KOKKOS_INLINE_FUNCTION VanGenuchtenSaturation
    vanGenuchtenSaturation( const RetentionParams& r, const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        const double s = p_w < 0.0 ? -p_w : 0.0;
        const double x = r.alpha_per_pa * s;
        if ( !( x > 0.0 ) )
            return VanGenuchtenSaturation{
                { r.s_sat, 0.0 }, true, 1.0, 0.0, 0.0 };
        const double m = 1.0 - 1.0 / r.n_vg;
        const VanGenuchtenTerms v = vanGenuchtenTerms( r.n_vg, x );
        const double s_e = KE::exp( -m * v.log_a );
        const double width = r.s_sat - r.s_res;
        return VanGenuchtenSaturation{
            { r.s_res + width * s_e, width * ( r.n_vg - 1.0 ) * s_e * v.q / s },
            false,
            s_e,
            m,
            v.d };
    }

    //! log(A), d = log(1 + x^-n) = -log(x^n / A) and q = x^n / A, A = 1 + x^n.
    struct VanGenuchtenTerms
    {
        double log_a;
        double d;
        double q;
    };

    //! \brief The terms of VanGenuchtenTerms for x = alpha s > 0 (-).
    KOKKOS_INLINE_FUNCTION static VanGenuchtenTerms
    vanGenuchtenTerms( const double n, const double x )
    {
        namespace KE = Kokkos::Experimental;
        const double log_xn = n * KE::log( x );
        const double xn = KE::exp( log_xn );
        // Split at x^n = 1 so neither log(A) nor d suffers cancellation.
        if ( xn > 1.0 )
        {
            const double inv_xn = 1.0 / xn;
            const double d = KE::log1p( inv_xn );
            return VanGenuchtenTerms{ log_xn + d, d, 1.0 / ( 1.0 + inv_xn ) };
        }
        const double log_a = KE::log1p( xn );
        return VanGenuchtenTerms{ log_a, log_a - log_xn, xn / ( 1.0 + xn ) };
    }

    /*!
      \brief Liakopoulos sand, Eqs. 12-13 with the corrected factor: S = 1 -
      1.9722e-11 s^2.4279 (s in Pa), k_rel = 1 - 2.207 (1 - S)^1.0121.

      Fitted for S > 0.91 (s < 9.5 kPa). Beyond it S keeps falling and is
      clamped at S = s_res (S >= 0 when s_res = 0; OGS uses S_min = 0.2) with
      dS/dp_w = 0 there; k_rel reaches 0 at S = 0.5426 (s = 18.6 kPa) and is
      floored at k_rel_min (porousLab: 1e-4). s_sat is not used (S_sat = 1).
    */
    KOKKOS_INLINE_FUNCTION RetentionState liakopoulos( const RetentionParams& r,
                                                       const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        const LiakopoulosSaturation l = liakopoulosSaturation( r, p_w );
        if ( l.saturated )
            return RetentionState{ 1.0, 0.0, 1.0 };
        const double k_rel =
            1.0 - 2.207 * KE::exp( 1.0121 * l.log_one_minus_s );
        return RetentionState{ l.state.S, l.state.dS_dp,
                               k_rel > r.k_rel_min ? k_rel : r.k_rel_min };
    }

    //! S and dS/dp_w of liakopoulos and the term k_rel needs.
    struct LiakopoulosSaturation
    {
        SaturationState state;
        bool saturated;         //!< p_w >= 0: S = 1, k_rel = 1
        double log_one_minus_s; //!< log(1 - S)
    };

    //! \brief S, dS/dp_w and log(1 - S) of liakopoulos at p_w (Pa).
    KOKKOS_INLINE_FUNCTION LiakopoulosSaturation
    liakopoulosSaturation( const RetentionParams& r, const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        if ( !( p_w < 0.0 ) )
            return LiakopoulosSaturation{ { 1.0, 0.0 }, true, 0.0 };
        constexpr double log_a = -24.64928635201841; // log(1.9722e-11)
        constexpr double b = 2.4279;
        const double s = -p_w;
        // 1 - S = a s^b, formed directly (no cancellation in k_rel).
        double log_one_minus_s = log_a + b * KE::log( s );
        const double one_minus_s = KE::exp( log_one_minus_s );
        double S = 1.0 - one_minus_s;
        double dS_dp = b * one_minus_s / s;
        if ( S < r.s_res )
        {
            // Clamped at the residual saturation.
            S = r.s_res;
            log_one_minus_s = KE::log( 1.0 - r.s_res );
            dS_dp = 0.0;
        }
        return LiakopoulosSaturation{ { S, dS_dp }, false, log_one_minus_s };
    }

    /*!
      \brief Gardner: psi = p_w / rho_w_g (m), S_e = exp(alpha psi) for psi <
      0 (alpha in 1/m), S = s_res + (s_sat - s_res) S_e, k_rel = S_e.
    */
    KOKKOS_INLINE_FUNCTION RetentionState gardner( const RetentionParams& r,
                                                   const double p_w ) const
    {
        namespace KE = Kokkos::Experimental;
        if ( !( p_w < 0.0 ) )
            return RetentionState{ r.s_sat, 0.0, 1.0 };
        const double c = r.alpha_per_m / r.rho_w_g; // 1/Pa
        const double s_e = KE::exp( c * p_w );
        const double width = r.s_sat - r.s_res;
        return RetentionState{ r.s_res + width * s_e, width * c * s_e,
                               s_e > r.k_rel_min ? s_e : r.k_rel_min };
    }

    /*!
      \brief Linear: S = s_sat - (s_sat - s_res) min(s / s_range, 1) with s =
      -p_w and s_range = suction_range_pa (Pa); k_rel = 1.
    */
    KOKKOS_INLINE_FUNCTION RetentionState linear( const RetentionParams& r,
                                                  const double p_w ) const
    {
        const double s = p_w < 0.0 ? -p_w : 0.0;
        const double width = r.s_sat - r.s_res;
        if ( !( s > 0.0 ) )
            return RetentionState{ r.s_sat, 0.0, 1.0 };
        if ( s >= r.suction_range_pa )
            return RetentionState{ r.s_res, 0.0, 1.0 };
        const double slope = width / r.suction_range_pa;
        return RetentionState{ r.s_sat - slope * s, slope, 1.0 };
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_RETENTION_HPP
