#include <mpm_test_backends.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( Liakopoulos );

//! Reference profile p_w(height) at one time (OpenGeoSys,
//! tests/data/reference).
std::map<int, std::vector<std::pair<double, double>>> readProfiles()
{
    std::ifstream in( RAINSLIDE_TEST_DATA_DIR
                      "/reference/liakopoulos_pressure_profiles.csv" );
    std::map<int, std::vector<std::pair<double, double>>> profiles;
    std::string line;
    std::getline( in, line ); // header
    while ( std::getline( in, line ) )
    {
        std::stringstream row( line );
        std::string t_min, t_s, height, p_w;
        std::getline( row, t_min, ',' );
        std::getline( row, t_s, ',' );
        std::getline( row, height, ',' );
        std::getline( row, p_w, ',' );
        profiles[std::stoi( t_min )].push_back(
            { std::stod( height ), std::stod( p_w ) } );
    }
    return profiles;
}

double interpolate( const std::vector<std::pair<double, double>>& f,
                    const double x )
{
    for ( std::size_t k = 1; k < f.size(); ++k )
        if ( x <= f[k].first )
            return f[k - 1].second + ( f[k].second - f[k - 1].second ) *
                                         ( x - f[k - 1].first ) /
                                         ( f[k].first - f[k - 1].first );
    return f.back().second;
}

//! Records snapshots of the drainage stage.
template <class ExecSpace>
class StageProbe : public mpm::RunObserver
{
  public:
    explicit StageProbe( const mpm::Simulation<ExecSpace>& sim )
        : _sim( sim )
    {
    }
    void onSnapshot( const mpm::RunProgress& progress,
                     const mpm::HostSnapshot& snapshot ) override
    {
        if ( progress.stage == "drainage" )
            snapshots[static_cast<int>( progress.stage_time_s / 60.0 + 0.5 )] =
                snapshot;
    }
    const mpm::Simulation<ExecSpace>& _sim;
    std::map<int, mpm::HostSnapshot> snapshots; // by minute
};

//---------------------------------------------------------------------------//
//! Tolerances of drainageAgainstReference, relative.
struct LiakopoulosTolerance
{
    double point, cell, outflow, settlement;
};

template <class TypeParam>
void drainageAgainstReference( const mpm::TwoPhaseScheme scheme,
                               const double courant_number,
                               const LiakopoulosTolerance& tolerance )
{
    auto config = mpm::readCaseFile( RAINSLIDE_CASES_DIR "/liakopoulos.toml" );
    config.solver.scheme = scheme;
    config.solver.courant_number = courant_number;
    const auto profiles = readProfiles();
    config.stages[1].duration_s = 60.0 * profiles.rbegin()->first + 1.0;
    config.stages[1].snapshot_interval_s = 0.0;
    config.stages[1].snapshot_times_s.clear();
    for ( const auto& profile : profiles )
        config.stages[1].snapshot_times_s.push_back( 60.0 * profile.first );
    mpm::Simulation<TypeParam> sim( config );
    StageProbe<TypeParam> probe( sim );
    mpm::runStages( sim, config, probe );

    const std::map<int, double> outflow_ref = {
        { 5, 3.394918e-06 }, { 10, 2.753338e-06 }, { 20, 2.035486e-06 } };
    const std::map<int, double> settlement_ref = {
        { 5, 0.541e-3 }, { 10, 0.760e-3 }, { 20, 1.004e-3 } };
    const double h = config.grid.cell_size_m;
    for ( const auto& [t, ref] : profiles )
    {
        ASSERT_TRUE( probe.snapshots.count( t ) ) << t << " min";
        const auto& snap = probe.snapshots.at( t );
        const double top_suction = std::abs( ref.back().second );
        std::map<int, std::array<double, 3>> cells; // sum p, sum y0, count
        double outflow = 0.0, settlement = 0.0, point_error = 0.0;
        int bottom = 0, top = 0;
        for ( int p = 0; p < snap.num_points; ++p )
        {
            const double y0 = snap.x[2 * p + 1] - snap.displacement[2 * p + 1];
            point_error = std::max(
                point_error, std::abs( snap.p_w[p] - interpolate( ref, y0 ) ) );
            auto& c = cells[static_cast<int>( y0 / h )];
            c[0] += snap.p_w[p];
            c[1] += y0;
            c[2] += 1.0;
            if ( y0 < h )
            {
                outflow -= snap.n[p] * snap.S[p] *
                           ( snap.v_w[2 * p + 1] - snap.v[2 * p + 1] );
                ++bottom;
            }
            if ( y0 > 1.0 - 0.5 * h )
            {
                settlement -= snap.displacement[2 * p + 1];
                ++top;
            }
        }
        double cell_error = 0.0;
        for ( const auto& [cell, c] : cells )
            cell_error = std::max(
                cell_error,
                std::abs( c[0] / c[2] - interpolate( ref, c[1] / c[2] ) ) );
        std::printf( "Liakopoulos %3d min: largest |p_w - reference| / top "
                     "suction: points %.4f, cell means %.4f\n",
                     t, point_error / top_suction, cell_error / top_suction );
        EXPECT_LT( point_error, tolerance.point * top_suction ) << t << " min";
        EXPECT_LT( cell_error, tolerance.cell * top_suction ) << t << " min";
        if ( !outflow_ref.count( t ) )
            continue;
        std::printf( "  outflow off by %.4f, settlement by %.4f\n",
                     outflow / bottom / outflow_ref.at( t ) - 1.0,
                     settlement / top / settlement_ref.at( t ) - 1.0 );
        EXPECT_NEAR( outflow / bottom, outflow_ref.at( t ),
                     tolerance.outflow * outflow_ref.at( t ) )
            << t << " min";
        EXPECT_NEAR( settlement / top, settlement_ref.at( t ),
                     tolerance.settlement * settlement_ref.at( t ) )
            << t << " min";
    }
}

// The paper's set-up (10 cells, 2 x 2 points) against OpenGeoSys at every
// reference time (2 ... 120 min): every point's p_w within 3 % of the top
// suction and every cell mean within 2.5 % (achieved: points <= 2.45 %,
// cells <= 1.9 %; a uniform p_w per cell gave points 4.3-7.7 %), over the
// first 20 minutes the bottom outflow within 3 % and the top settlement
// within 8 %.
TYPED_TEST( Liakopoulos, drainage_matches_reference_point_by_point )
{
    drainageAgainstReference<TypeParam>( mpm::TwoPhaseScheme::Explicit, 0.5,
                                         { 0.03, 0.025, 0.03, 0.08 } );
}

// The semi-implicit scheme (docs/formulation.md §9) at 0.4 times the case's
// Courant number: its step, 0.14 s, is still 18 times the explicit one.
// Achieved (with the explicit scheme's PIC damping per second): points
// <= 2.0 %, cells <= 1.6 %, outflow 1.0-1.5 %, settlement 3.2-3.6 %; first
// order in time, so at the case's 0.5 the points are 4.9 % off at 5 min
// (2.6 % at 0.25, 2.2 % at 0.1).
TYPED_TEST( Liakopoulos, semi_implicit_drainage_matches_reference )
{
    drainageAgainstReference<TypeParam>( mpm::TwoPhaseScheme::SemiImplicit, 0.2,
                                         { 0.03, 0.025, 0.03, 0.08 } );
}

//---------------------------------------------------------------------------//
// The paper's permeability, k = 1e-13 m^2, without inertia scaling: the
// implicit drag keeps the step independent of permeability, so the run is
// stable at the paper's dt = 5e-6 s and at the wave-speed limit (the
// explicit-drag limit would be 5.5e-7 s, verification.md 6).
TYPED_TEST( Liakopoulos, low_permeability_is_stable_at_paper_and_cfl_steps )
{
    for ( const double dt : { 5.0e-6, 0.0 } )
    {
        auto config =
            mpm::readCaseFile( RAINSLIDE_CASES_DIR "/liakopoulos.toml" );
        config.materials[0].permeability_m2 = 1.0e-13;
        for ( auto& stage : config.stages )
            stage.materials[0].permeability_m2 = 1.0e-13;
        config.solver.inertia_scaling = 1.0;
        config.solver.dt_s = dt;
        config.stages[0].duration_s = 0.05;
        config.stages[1].duration_s = dt > 0.0 ? 0.2 : 1.0;
        mpm::Simulation<TypeParam> sim( config );
        mpm::RunObserver observer;
        EXPECT_NO_THROW( mpm::runStages( sim, config, observer ) )
            << "dt = " << dt;
        if ( dt > 0.0 )
        {
            // The paper's step is admissible.
            EXPECT_LT( dt, sim.waveSpeedLimit().dt_limit );
        }
        const auto snap = mpm::hostSnapshot( sim );
        double v_max = 0.0;
        for ( std::size_t k = 0; k < snap.v.size(); ++k )
            v_max = std::max(
                { v_max, std::abs( snap.v[k] ), std::abs( snap.v_w[k] ) } );
        // The gravity load leaves elastic oscillations (static settlement
        // ~3 mm, drained period ~0.1 s: ~0.2 m/s); an instability grows
        // without bound.
        EXPECT_LT( v_max, 0.5 ) << "dt = " << dt; // m/s
        for ( const double p : snap.p_w )
            ASSERT_TRUE( std::isfinite( p ) );
    }
}

} // namespace
