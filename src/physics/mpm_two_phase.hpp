#ifndef MPM_TWO_PHASE_HPP
#define MPM_TWO_PHASE_HPP

#include <physics/mpm_material_params.hpp>
#include <physics/mpm_nodal_water.hpp>
#include <physics/mpm_retention.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Implicit-drag nodal update of the two-phase momentum balance, one
  node and one direction (docs/formulation.md, step 2; Eqs. 9-10):
    (m_w/dt + Q) v_w' - Q v_s'          = m_w/dt v_w + F_w
    -Q v_w'          + (m_s/dt + Q) v_s' = m_s/dt v_s + F_m - F_w
  with the drag coefficient Q (kg/s) at the new time, so no permeability
  limits the step. A fixed solid sets v_s' = 0; an impermeable boundary
  ties v_w' = v_s' + w_tied (w_tied = 0, or the seepage of a prescribed
  flux: tiedSeepage); the remaining scalar equation is then solved.
  Local damping reduces the mixture force by damping |F_m| along v_s; the
  water force is not damped (the drag already dissipates, and damping it
  would slow consolidation).
*/
struct TwoPhaseNodalUpdate
{
    double dt;                    //!< time step, s
    double damping;               //!< local damping coefficient
    double inertia_scaling = 1.0; //!< factor on the inertial masses

    struct Result
    {
        double v_s, v_w;   //!< new velocities, m/s
        double dv_s, dv_w; //!< velocity increments, m/s
    };

    KOKKOS_INLINE_FUNCTION static double sign( const double v )
    {
        return ( v > 0.0 ) - ( v < 0.0 );
    }

    KOKKOS_INLINE_FUNCTION Result
    operator()( const double m_s, const double m_w, const double mv_s,
                const double mv_w, double f_m, double f_w, const double q,
                const bool solid_fixed, const bool water_tied,
                const double w_tied = 0.0 ) const
    {
        namespace KE = Kokkos::Experimental;
        const double v_s = mv_s / m_s;
        // A node with (almost) no water moves its water with the solid.
        const bool has_water = hasWater( m_w, m_s );
        const double v_w = has_water ? mv_w / m_w : v_s;
        f_m -= damping * KE::fabs( f_m ) * sign( v_s );

        const double a_w = inertia_scaling * m_w / dt;
        const double a_s = inertia_scaling * m_s / dt;
        const double b_w = a_w * v_w + f_w;
        const double b_s = a_s * v_s + f_m - f_w;
        Result r;
        if ( solid_fixed )
        {
            r.v_s = 0.0;
            r.v_w = !has_water ? 0.0 : water_tied ? w_tied : b_w / ( a_w + q );
        }
        else if ( water_tied && has_water )
        {
            // v_w' = v_s' + w_tied in the sum of both equations (the
            // mixture: the drag cancels).
            r.v_s = ( b_w + b_s - a_w * w_tied ) / ( a_w + a_s );
            r.v_w = r.v_s + w_tied;
        }
        else if ( !has_water || !( q < 1.0e300 ) )
        {
            // v_w' = v_s': the sum of both equations (the mixture); also
            // the limit of an infinite drag (k_rel = 0 at every point).
            r.v_s = ( b_w + b_s ) / ( a_w + a_s );
            r.v_w = r.v_s;
        }
        else
        {
            const double det = a_w * a_s + q * ( a_w + a_s );
            r.v_w = ( ( a_s + q ) * b_w + q * b_s ) / det;
            r.v_s = ( q * b_w + ( a_w + q ) * b_s ) / det;
        }
        r.dv_s = r.v_s - v_s;
        r.dv_w = r.v_w - v_w;
        return r;
    }
};

//---------------------------------------------------------------------------//
//! Above this, exp(-x) rounds to 0 in double precision (< 2^-1075).
constexpr double max_exp_decay = 746.0;

/*!
  \brief Share of the part of a point's seepage velocity w = v_w - v_s that
  the grid does not carry kept over a step (mpm::twoPhaseBlend): the drag's
  decay exp(-dt / tau), tau = f rho_w k k_rel / (n S mu) the relaxation time
  of Eq. 9 at the point (the water's inertial mass f n S rho_w V, f the
  inertia scaling, over the drag (n S)^2 mu V / (k k_rel); the solid's
  share of the relaxation left out), but not less than the FLIP share
  `flip_fraction`. The floor: where k_rel is small the drag would relax w
  within a step to the grid's w_pic, which below a wetting front is the
  seepage of the wet nodes of the point's cell; the near-dry points then
  carried it to their locked nodes each step, where the drag handed it to
  the solid (a wetted column rang: 9.7 J against 0.31 J). Saturated slope
  soil: tau = 15 ms, exp(-dt / tau) = 0.980 at a 3e-4 s step (the floor,
  0.99, applies), 0.9993 at 1e-5 s.
*/
KOKKOS_INLINE_FUNCTION double
seepageMemory( const double dt, const double n, const double S,
               const double permeability, const double k_rel,
               const double viscosity, const double density,
               const double inertia_scaling, const double flip_fraction )
{
    namespace KE = Kokkos::Experimental;
    const double mobility = permeability * k_rel;
    if ( !( mobility > 0.0 ) )
        return flip_fraction;
    const double decay =
        dt * n * S * viscosity / ( inertia_scaling * density * mobility );
    // exp(-decay) is exactly 0 there; the library's underflow path (errno,
    // flags) cost 3 % of a slope run, where the dry soil's k_rel is tiny.
    if ( decay > max_exp_decay )
        return KE::fmax( flip_fraction, 0.0 );
    return KE::fmax( flip_fraction, KE::exp( -decay ) );
}

//---------------------------------------------------------------------------//
/*!
  \brief Newton iteration of the mass-conservative pore-pressure increment
  of one point (Eq. 8, docs/formulation.md step 6): solves for dp
    n (S(p + dp) - S(p)) + n S dp / K_w = -dt (n S div v_w + (1 - n) S div v_s)
  (the right side is `volume_change`, dimensionless), safeguarded by
  bisection (the left side is monotone in dp). Each step() takes the
  saturation state (S, dS/dp_w) at pressure() and sets `done` once
  converged.
*/
struct PorePressureNewton
{
    static constexpr int max_iterations = 50;

    double p_w;           //!< pressure at the start of the step, Pa
    double S;             //!< saturation at the start of the step
    double n;             //!< porosity
    double storage;       //!< n S / K_w, 1/Pa
    double volume_change; //!< right side of the equation
    double lo, hi;        //!< bracket of the root, Pa
    double dp;            //!< current increment, Pa
    bool done;            //!< converged (or nothing to solve)

    PorePressureNewton() = default;

    KOKKOS_INLINE_FUNCTION
    PorePressureNewton( const double p_w_start, const double S_start,
                        const double porosity, const double bulk_modulus,
                        const double water_volume_change )
        : p_w( p_w_start )
        , S( S_start )
        , n( porosity )
        , storage( porosity * S_start / bulk_modulus )
        , volume_change( water_volume_change )
        // Bracket: the storage term alone bounds the root.
        , lo( water_volume_change < 0.0 ? water_volume_change / storage : 0.0 )
        , hi( water_volume_change > 0.0 ? water_volume_change / storage : 0.0 )
        , dp( 0.0 )
        , done( false )
    {
    }

    //! Pressure of the next retention evaluation, p_w + dp.
    KOKKOS_INLINE_FUNCTION double pressure() const { return p_w + dp; }

    //! One safeguarded Newton step from the state at pressure().
    KOKKOS_INLINE_FUNCTION void step( const SaturationState& state )
    {
        namespace KE = Kokkos::Experimental;
        const double g = n * ( state.S - S ) + storage * dp - volume_change;
        if ( g > 0.0 )
            hi = dp;
        else
            lo = dp;
        const double slope = n * state.dS_dp + storage;
        double next = dp - g / slope;
        // The bracket's ends included: where S is constant (a saturated
        // point) the first Newton step lands exactly on the storage bound,
        // the root; excluding it bisected to within 1e-9 Pa instead, up to
        // 50 retention evaluations per point and step (PorePressureNewton
        // tests).
        if ( !( next >= lo && next <= hi ) )
            next = 0.5 * ( lo + hi );
        const double change = KE::fabs( next - dp );
        dp = next;
        done =
            change <= 1.0e-12 * ( KE::fabs( p_w ) + KE::fabs( dp ) ) + 1.0e-9;
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Runs the PorePressureNewton iterations of `Lanes` points in lock
  step (each point's iterates are those of porePressureIncrement). The
  retention evaluations of different points are independent, so their
  latency chains (exp, log) overlap: 4 lanes took a third less time than
  one point after the other. `retention[l](p)` gives the saturation state
  of lane l at pressure p; with `states_known`, state_at_p_w[l] is
  retention[l](p_w) (it saves the first evaluation, same result). Lanes
  already `done` are skipped.
*/
template <int Lanes, class RetentionFunction>
KOKKOS_INLINE_FUNCTION void
porePressureIncrements( const RetentionFunction ( &retention )[Lanes],
                        PorePressureNewton ( &newton )[Lanes],
                        const SaturationState ( &state_at_p_w )[Lanes],
                        const bool states_known )
{
    for ( int iter = 0; iter < PorePressureNewton::max_iterations; ++iter )
    {
        SaturationState state[Lanes] = {};
        bool any = false;
        for ( int l = 0; l < Lanes; ++l )
        {
            if ( newton[l].done )
                continue;
            any = true;
            state[l] = ( iter == 0 && states_known )
                           ? state_at_p_w[l]
                           : retention[l]( newton[l].pressure() );
        }
        if ( !any )
            return;
        for ( int l = 0; l < Lanes; ++l )
            if ( !newton[l].done )
                newton[l].step( state[l] );
    }
}

//---------------------------------------------------------------------------//
/*!
  \brief Mass-conservative pore-pressure increment dp of one point
  (PorePressureNewton). `retention(p)` returns the saturation state (S,
  dS/dp_w) at pressure p. `state_at_p_w`, if not null, is retention(p_w),
  known from the last update (it saves the first evaluation, same result).
*/
template <class RetentionFunction>
KOKKOS_INLINE_FUNCTION double
porePressureIncrement( const RetentionFunction& retention, const double p_w,
                       const double S, const double n,
                       const double bulk_modulus, const double volume_change,
                       const SaturationState* state_at_p_w = nullptr )
{
    PorePressureNewton newton( p_w, S, n, bulk_modulus, volume_change );
    for ( int iter = 0;
          iter < PorePressureNewton::max_iterations && !newton.done; ++iter )
        newton.step( ( iter == 0 && state_at_p_w )
                         ? *state_at_p_w
                         : retention( newton.pressure() ) );
    return newton.dp;
}

//---------------------------------------------------------------------------//
/*!
  \brief Water equilibrium inside a cell (a stabilised Eq. 8): after the
  point-wise mass balance of a step, the points of a cell (those without a
  prescribed p_w) take the pressure P + d_i of one profile across the
  cell (d_i = s . (x_i - x_c), the cell's limited slope s: 0 for a uniform
  pressure; limitedPressureSlope), its level P the one that holds their
  water:
    sum_i a_i (S_i(P + d_i) - S_i) + sum_i a_i S_i (P + d_i - p_i) / K_w = 0,
  a_i = V_i n_i, solved by a safeguarded Newton iteration (the left side
  grows with P; P lies between the smallest and largest p_i - d_i).

  The nodal forces cannot see a pressure that alternates from point to
  point inside a cell (the hourglass mode of four points on a bilinear
  cell), nor, in a cell with fixed nodes, the pressures that act only on
  those nodes; once a staircase base or a front excites such a mode
  nothing corrects it. Water inside one cell equilibrates within h^2/c_v,
  well below a step's resolution of the flow between cells (for the slope
  soil about 4 ms against the 0.25 s the wetting front takes to cross a
  cell), so one pressure per cell removes those modes and no physics the
  grid resolves. The water of the cell is conserved exactly (the
  retention law is evaluated, not linearised), so a front inside a cell
  keeps its water and spreads over the cell.
*/
struct CellWaterEquilibrium
{
    static constexpr int max_iterations = 60;
    static constexpr int max_cached = 16; //!< points gathered once per solve
    double bulk_modulus;                  //!< K_w, Pa

    //! What the solve needs of a point.
    struct Point
    {
        double a;   //!< V n, m^3
        double S;   //!< saturation before
        double p_w; //!< pressure before, Pa
        double d;   //!< its pressure relative to the cell's level P, Pa
        const RetentionParams* retention;
    };

    //! The level P of the `count` points point_at(0..count) (point i takes
    //! P + d_i); `changed` is false if they already lie on the profile.
    template <class PointAt>
    KOKKOS_INLINE_FUNCTION double
    solve( const int count, const PointAt& point_at, bool& changed ) const
    {
        namespace KE = Kokkos::Experimental;
        // The first points gathered once (a cell holds a few), the others
        // at each use.
        Point cached[max_cached];
        const int num_cached = count < max_cached ? count : max_cached;
        for ( int i = 0; i < num_cached; ++i )
            cached[i] = point_at( i );
        const auto point = [&]( const int i )
        { return i < max_cached ? cached[i] : point_at( i ); };
        double lo = 1.0e300, hi = -1.0e300, weighted = 0.0, weight = 0.0;
        for ( int i = 0; i < count; ++i )
        {
            const Point q = point( i );
            const double level = q.p_w - q.d;
            lo = level < lo ? level : lo;
            hi = level > hi ? level : hi;
            weighted += q.a * q.S * level;
            weight += q.a * q.S;
        }
        changed = hi - lo > 1.0e-9 * ( KE::fabs( hi ) + 1.0 );
        if ( !changed )
            return lo;
        double P = weight > 0.0 ? weighted / weight : 0.5 * ( lo + hi );
        P = P > lo && P < hi ? P : 0.5 * ( lo + hi );
        for ( int iter = 0; iter < max_iterations; ++iter )
        {
            double g = 0.0, slope = 0.0;
            for ( int i = 0; i < count; ++i )
            {
                const Point q = point( i );
                const SaturationState state =
                    Retention{}.saturationState( *q.retention, P + q.d );
                g += q.a * ( state.S - q.S ) +
                     q.a * q.S * ( P + q.d - q.p_w ) / bulk_modulus;
                slope += q.a * ( state.dS_dp + q.S / bulk_modulus );
            }
            if ( g > 0.0 )
                hi = P;
            else
                lo = P;
            double next = P - g / slope;
            // The bracket's ends included: a step that rounds to no step
            // (g = 0 or below one ulp of P, e.g. the exact level of a
            // saturated cell) has converged; excluding it bisected away
            // from the level, adding water (~1e-10 of the inflow, tests/
            // regression/tst_polyline_inflow.cpp).
            if ( !( next >= lo && next <= hi ) )
                next = 0.5 * ( lo + hi );
            const double change = KE::fabs( next - P );
            P = next;
            if ( change <= 1.0e-12 * ( KE::fabs( P ) + 1.0 ) + 1.0e-9 )
                break;
        }
        return P;
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_TWO_PHASE_HPP
