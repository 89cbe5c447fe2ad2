#ifndef MPM_TEST_HARD_CASES_HPP
#define MPM_TEST_HARD_CASES_HPP

// Helpers of the hard-case regression tests (regression/tst_hard_cases_*.cpp):
// the unsaturated column and its stages, checks of a snapshot, a recorder
// of the run, the wetting front's depth and Green-Ampt's time.
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mpm_test
{
namespace hard_cases
{
//! The fixture of the HardCases suite. Its tests are in several files: one
//! class for all of them (GoogleTest requires one fixture class per suite),
//! so it is defined here, outside the files' anonymous namespaces.
template <class ExecSpace>
class HardCases : public ::testing::Test
{
};

inline constexpr double gravity = 9.81; // m/s^2
inline constexpr double rho_water = 1000.0;

//! Constrained (oedometric) modulus E (1 - nu) / ((1 + nu)(1 - 2 nu)).
inline double constrainedModulus( const mpm::MaterialConfig& m )
{
    const double E = m.youngs_modulus_pa, nu = m.poisson_ratio;
    return E * ( 1.0 - nu ) / ( ( 1.0 + nu ) * ( 1.0 - 2.0 * nu ) );
}

//! van Genuchten S(p_w) of a material (p_w < 0 in suction).
inline double vanGenuchtenS( const mpm::RetentionConfig& r, const double p_w )
{
    const double s = std::max( -p_w, 0.0 );
    const double m = 1.0 - 1.0 / r.n;
    const double s_e =
        std::pow( 1.0 + std::pow( r.alpha_per_pa * s, r.n ), -m );
    return r.residual_saturation +
           ( r.saturated_saturation - r.residual_saturation ) * s_e;
}

//! Mualem relative permeability of the van Genuchten law at saturation S.
inline double mualemKrel( const mpm::RetentionConfig& r, const double S )
{
    const double s_e = ( S - r.residual_saturation ) /
                       ( r.saturated_saturation - r.residual_saturation );
    const double m = 1.0 - 1.0 / r.n;
    const double f = 1.0 - std::pow( 1.0 - std::pow( s_e, 1.0 / m ), m );
    return std::sqrt( s_e ) * f * f;
}

//! Holds p_w = pressure on every point of the scene.
inline mpm::PorePressureCondition holdEverywhere( const double pressure )
{
    mpm::PorePressureCondition c;
    c.points.kind = mpm::PointSelection::Kind::Box;
    c.points.box_m = { mpm::Point2{ -1.0e3, -1.0e3 },
                       mpm::Point2{ 1.0e3, 1.0e3 } };
    c.pressure_pa = pressure;
    return c;
}

/*!
  An unsaturated column of the paper's soil (one cell wide, rollers on the
  sides, fixed impermeable base, free surface two cells below the top of
  the grid) at a uniform suction, and a geostatic stage: gravity with the
  suction held on every point, damped (local damping 0.7) until at rest,
  displacements reset at its end.
*/
inline mpm::CaseConfig unsaturatedColumn( const double H, const double h,
                                          const double suction,
                                          const double geostatic_s )
{
    mpm::StageConfig geostatic;
    geostatic.name = "geostatic";
    geostatic.type = mpm::StageType::Dynamic;
    geostatic.damping = 0.7;
    geostatic.duration_s = geostatic_s;
    geostatic.reset_displacement = true;
    auto config = mpm_test::columnCase( H, h, paperSoil(), geostatic );
    config.analysis = mpm::AnalysisType::Unsaturated;
    config.bodies[0].initial_pore_pressure_pa = -suction;
    config.stages[0].pore_pressures = { holdEverywhere( -suction ) };
    return config;
}

//! A stage that continues `previous` without damping or prescriptions.
inline mpm::StageConfig freeStage( const mpm::StageConfig& previous,
                                   const std::string& name,
                                   const double duration )
{
    mpm::StageConfig stage = previous;
    stage.name = name;
    stage.type = mpm::StageType::Dynamic;
    stage.damping = 0.0;
    stage.duration_s = duration;
    stage.reset_displacement = false;
    stage.pore_pressures.clear();
    stage.loads.clear();
    stage.snapshot_interval_s = 0.0;
    stage.snapshot_times_s.clear();
    return stage;
}

//! Number of non-finite values among every field of a snapshot.
inline int countNonFinite( const mpm::HostSnapshot& snap )
{
    int bad = 0;
    for ( const auto* field :
          { &snap.x, &snap.displacement, &snap.v, &snap.sigma, &snap.eps,
            &snap.vol, &snap.mass, &snap.p_w, &snap.S, &snap.n, &snap.v_w,
            &snap.k_rel } )
        for ( const double value : *field )
            if ( !std::isfinite( value ) )
                ++bad;
    return bad;
}

//! Largest |v| of the solid (and the water in two-phase scenes), m/s.
inline double maxSpeed( const mpm::HostSnapshot& snap )
{
    double v_max = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        v_max =
            std::max( v_max, std::hypot( snap.v[2 * p], snap.v[2 * p + 1] ) );
        if ( !snap.v_w.empty() )
            v_max = std::max(
                v_max, std::hypot( snap.v_w[2 * p], snap.v_w[2 * p + 1] ) );
    }
    return v_max;
}

//! Total mixture mass sum m_s + n S rho_w V, kg (per metre).
inline double mixtureMass( const mpm::HostSnapshot& snap )
{
    double mass = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
        mass += snap.mass[p] +
                ( snap.p_w.empty()
                      ? 0.0
                      : snap.n[p] * snap.S[p] * rho_water * snap.vol[p] );
    return mass;
}

/*!
  Records the largest kinetic energy (of the solid, as runStages reports
  it) of each stage and the snapshots the stages ask for, by stage and
  stage time.
*/
class Recorder : public mpm::RunObserver
{
  public:
    void onStep( const mpm::RunProgress& progress ) override
    {
        auto& ke = ke_max[progress.stage_index];
        ke = std::max( ke, progress.kinetic_energy_j );
    }
    void onSnapshot( const mpm::RunProgress& progress,
                     const mpm::HostSnapshot& snapshot ) override
    {
        snapshots[progress.stage_index].push_back(
            { progress.stage_time_s, snapshot } );
    }
    std::map<int, double> ke_max;
    std::map<int, std::vector<std::pair<double, mpm::HostSnapshot>>> snapshots;
};

/*!
  Mean of a point field over the points of each cell (by initial height):
  cell -> (mean initial height, mean value).
*/
inline std::map<int, std::pair<double, double>>
cellMeans( const mpm::HostSnapshot& snap, const std::vector<double>& field,
           const double h )
{
    std::map<int, std::array<double, 3>> sums;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const double y0 = snap.x[2 * p + 1] - snap.displacement[2 * p + 1];
        auto& s = sums[static_cast<int>( std::floor( y0 / h ) )];
        s[0] += field[p];
        s[1] += y0;
        s[2] += 1.0;
    }
    std::map<int, std::pair<double, double>> means;
    for ( const auto& [cell, s] : sums )
        means[cell] = { s[1] / s[2], s[0] / s[2] };
    return means;
}

//! Depth (below the initial surface H) where a row-averaged field, scanned
//! from the surface down, first falls below `level` (linear interpolation
//! between rows of points, by initial height).
inline double frontDepth( const mpm::HostSnapshot& snap,
                          const std::vector<double>& field, const double level,
                          const double H )
{
    std::map<long, std::array<double, 3>> rows; // key -> (y0, value, count)
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const double y0 = snap.x[2 * p + 1] - snap.displacement[2 * p + 1];
        auto& r = rows[std::lround( y0 * 1.0e6 )];
        r[0] += y0;
        r[1] += field[p];
        r[2] += 1.0;
    }
    double y_above = H, value_above = 0.0;
    bool first = true;
    for ( auto it = rows.rbegin(); it != rows.rend(); ++it )
    {
        const double y = it->second[0] / it->second[2];
        const double value = it->second[1] / it->second[2];
        if ( value < level )
        {
            if ( first )
                return 0.0;
            const double f = ( value_above - level ) / ( value_above - value );
            return H - ( y_above + f * ( y - y_above ) );
        }
        first = false;
        y_above = y;
        value_above = value;
    }
    return H;
}

//! Green–Ampt time (s) for a front at depth z below a ponded surface.
inline double greenAmptTime( const double z, const double K,
                             const double d_theta, const double h_f )
{
    return d_theta / K * ( z - h_f * std::log( 1.0 + z / h_f ) );
}

//! Moves every point up so that the top row lies exactly at y_top
//! (positions and reference positions).
template <class ExecSpace>
void liftTopRowTo( mpm::Simulation<ExecSpace>& sim, const double y_top )
{
    auto x = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                  sim.particles.x_p );
    double y_max = -1.0e300;
    for ( std::size_t p = 0; p < x.extent( 0 ); ++p )
        y_max = std::max( y_max, x( p, 1 ) );
    for ( std::size_t p = 0; p < x.extent( 0 ); ++p )
        x( p, 1 ) = x( p, 1 ) == y_max ? y_top : x( p, 1 ) + ( y_top - y_max );
    Kokkos::deep_copy( sim.particles.x_p, x );
    Kokkos::deep_copy( sim.particles.x0_p, x );
}

} // namespace hard_cases
} // namespace mpm_test

#endif // MPM_TEST_HARD_CASES_HPP
