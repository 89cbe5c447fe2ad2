// The stable step of points that stretch (issue 13): a tall sand block
// released from a gate spreads over a no-slip base and the points of its
// front stretch to J = V / V0 > 4. With moduli that fall with dilation, K / J
// and G / J (solver.moduli_fall_with_dilation, the default), a point's P
// wave does not grow with J, so the step stays at the undeformed one; with
// constant moduli it is sqrt(J) times faster and the step falls with it.
#include <mpm_test_backends.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( StretchedPoints );

//! The largest volume ratio V / V0 over the snapshots and the release
//! stage's smallest and largest stable steps.
class StretchWatcher : public mpm::RunObserver
{
  public:
    void onSnapshot( const mpm::RunProgress&,
                     const mpm::HostSnapshot& snap ) override
    {
        if ( _vol0.empty() )
            _vol0 = snap.vol; // no point leaves: the order is kept
        for ( int p = 0; p < snap.num_points; ++p )
            max_volume_ratio =
                std::max( max_volume_ratio, snap.vol[p] / _vol0[p] );
        max_x = 0.0;
        for ( int p = 0; p < snap.num_points; ++p )
            max_x = std::max( max_x, snap.x[2 * p] );
    }
    void onStageEnd( const mpm::RunProgress&,
                     const mpm::StageSummary& summary ) override
    {
        dt_min_s = summary.dt_min_s;
        dt_max_s = summary.dt_max_s;
    }

    double max_volume_ratio = 0.0, max_x = 0.0;
    double dt_min_s = 0.0, dt_max_s = 0.0;

  private:
    std::vector<double> _vol0;
};

//! cases/gate_collapse.toml made tall: a 0.5 m x 1 m block on 80 x 24 cells
//! of 0.05 m held by a gate at x = 0.5 m, then released for 3 s (the deposit
//! is at rest after 1.2 s).
mpm::CaseConfig tallGateCollapse( const bool moduli_fall_with_dilation )
{
    mpm::CaseConfig config =
        mpm::readCaseFile( RAINSLIDE_CASES_DIR "/gate_collapse.toml" );
    config.grid.cells = { 80, 24 };
    config.bodies.at( 0 ).polygon_m = {
        { 0.0, 0.0 }, { 0.5, 0.0 }, { 0.5, 1.0 }, { 0.0, 1.0 } };
    for ( mpm::StageConfig& stage : config.stages )
        for ( mpm::BoundaryConfig& b : stage.boundaries )
            if ( b.where == mpm::BoundarySelector::Polyline )
                b.polyline_m = { { 0.5, 0.0 }, { 0.5, 1.2 } };
    mpm::StageConfig& release = config.stages.at( 1 );
    release.duration_s = 3.0;
    release.snapshot_interval_s = 0.1;
    config.solver.moduli_fall_with_dilation = moduli_fall_with_dilation;
    return config;
}

template <class ExecSpace>
StretchWatcher run( const mpm::CaseConfig& config )
{
    mpm::Simulation<ExecSpace> sim( config );
    StretchWatcher watcher;
    mpm::runStages( sim, config, watcher );
    return watcher;
}

//---------------------------------------------------------------------------//
// The undeformed step is C h / sqrt(E_c / rho) (4.09e-4 s). Measured: with
// moduli that fall with dilation the smallest step is 1.05x below it
// (the front's speed, 3 m/s against a P wave of 61 m/s), the front's points
// stretch to J = 4.6 and the deposit runs out to x = 1.63 m; with constant
// moduli 2.14x below it (J = 4.6, run-out 1.56 m).
TYPED_TEST( StretchedPoints, step_stays_at_the_undeformed_one )
{
    const mpm::CaseConfig config = tallGateCollapse( true );
    const mpm::MaterialConfig& sand = config.materials.at( 0 );
    const double nu = sand.poisson_ratio;
    const double e_c = sand.youngs_modulus_pa * ( 1.0 - nu ) /
                       ( ( 1.0 + nu ) * ( 1.0 - 2.0 * nu ) );
    const double dt_undeformed = config.solver.courant_number *
                                 config.grid.cell_size_m /
                                 std::sqrt( e_c / sand.density_kg_per_m3 );

    const auto falling = run<TypeParam>( config );
    const auto constant = run<TypeParam>( tallGateCollapse( false ) );
    std::printf( "  falling moduli:  J max %.2f, dt %.3g..%.3g s (%.3fx "
                 "below %.3g s), run-out to x = %.3f m\n",
                 falling.max_volume_ratio, falling.dt_min_s, falling.dt_max_s,
                 dt_undeformed / falling.dt_min_s, dt_undeformed,
                 falling.max_x );
    std::printf( "  constant moduli: J max %.2f, dt %.3g..%.3g s (%.3fx "
                 "below), run-out to x = %.3f m\n",
                 constant.max_volume_ratio, constant.dt_min_s,
                 constant.dt_max_s, dt_undeformed / constant.dt_min_s,
                 constant.max_x );

    // The points do stretch, in both runs.
    EXPECT_GT( falling.max_volume_ratio, 4.0 );
    EXPECT_GT( constant.max_volume_ratio, 4.0 );
    // The step: within 1.15x of the undeformed one (the issue asks for
    // 2x); the control falls below half of it.
    EXPECT_NEAR( falling.dt_max_s, dt_undeformed, 1.0e-3 * dt_undeformed );
    EXPECT_GT( falling.dt_min_s, dt_undeformed / 1.15 );
    EXPECT_LT( constant.dt_min_s, dt_undeformed / 2.0 );
    // The deposit: the two run-outs within 10 % of each other.
    EXPECT_NEAR( falling.max_x, constant.max_x, 0.1 * constant.max_x );
}

} // namespace
