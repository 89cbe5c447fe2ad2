// The factor-of-safety search (bracketing + bisection) with fake trial
// functions, the trial verdict and the strength reduction: host only.
#include <solver/drivers/mpm_fos_criterion.hpp>
#include <solver/drivers/mpm_fos_search.hpp>
#include <solver/drivers/mpm_fos_trial.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

namespace
{
//! Search with a trial that fails above `answer` and records every F.
mpm::FosSearchResult searchWithAnswer( const mpm::FosSearchSettings& s,
                                       const double answer,
                                       std::multiset<double>* tried = nullptr )
{
    return mpm::searchFactorOfSafety( s,
                                      [&]( const double factor )
                                      {
                                          if ( tried )
                                              tried->insert( factor );
                                          return mpm::FosVerdict{ factor >
                                                                  answer };
                                      } );
}

void expectBracketed( const mpm::FosSearchResult& r,
                      const mpm::FosSearchSettings& s, const double answer )
{
    ASSERT_TRUE( r.found ) << r.status;
    EXPECT_EQ( r.status, "found" );
    EXPECT_LE( r.stable, answer );
    EXPECT_GT( r.failing, answer );
    EXPECT_LE( r.failing - r.stable, 2.0 * s.tolerance + 1e-12 );
    EXPECT_NEAR( r.factor, answer, s.tolerance + 1e-12 );
    EXPECT_DOUBLE_EQ( r.factor, 0.5 * ( r.stable + r.failing ) );
    ASSERT_EQ( r.trial_factors.size(), r.trial_fails.size() );
    for ( std::size_t i = 0; i < r.trial_factors.size(); ++i )
        EXPECT_EQ( r.trial_fails[i], r.trial_factors[i] > answer );
}
} // namespace

TEST( FosSearch, finds_the_transition_from_below_and_above )
{
    mpm::FosSearchSettings s;
    for ( const double start : { 0.3, 1.0, 1.39, 1.41, 2.0, 9.0 } )
        for ( const double answer : { 0.12, 0.7, 1.0, 1.3937, 2.5, 7.31 } )
        {
            s.start = start;
            std::multiset<double> tried;
            const auto r = searchWithAnswer( s, answer, &tried );
            SCOPED_TRACE( "start " + std::to_string( start ) + " answer " +
                          std::to_string( answer ) );
            expectBracketed( r, s, answer );
            // Every F within the limits, none tried twice.
            for ( const double f : tried )
            {
                EXPECT_GE( f, s.min_factor );
                EXPECT_LE( f, s.max_factor );
                EXPECT_EQ( tried.count( f ), 1u );
            }
        }
}

TEST( FosSearch, a_start_near_the_answer_needs_few_trials )
{
    mpm::FosSearchSettings s;
    s.start = 1.35;
    s.step = 0.05;
    const auto r = searchWithAnswer( s, 1.39 );
    expectBracketed( r, s, 1.39 );
    // 1.35 stable, 1.40 fails, then bisection of 0.05 down to 0.02: 2 more.
    EXPECT_LE( r.trial_factors.size(), 4u );
}

TEST( FosSearch, tolerance_sets_the_bracket )
{
    mpm::FosSearchSettings s;
    s.tolerance = 1e-4;
    const auto r = searchWithAnswer( s, 1.23456 );
    expectBracketed( r, s, 1.23456 );
    EXPECT_LE( r.failing - r.stable, 2e-4 );
}

TEST( FosSearch, reports_no_transition_within_the_limits )
{
    mpm::FosSearchSettings s;
    s.max_factor = 5.0;
    auto r = searchWithAnswer( s, 50.0 );
    EXPECT_FALSE( r.found );
    EXPECT_EQ( r.status, "stable_at_max_factor" );
    EXPECT_DOUBLE_EQ( r.stable, 5.0 );
    EXPECT_EQ( r.failing, 0.0 );

    s.min_factor = 0.05;
    r = searchWithAnswer( s, 0.01 );
    EXPECT_FALSE( r.found );
    EXPECT_EQ( r.status, "fails_at_min_factor" );
    EXPECT_DOUBLE_EQ( r.failing, 0.05 );
    EXPECT_EQ( r.stable, 0.0 );
}

TEST( FosSearch, stops_after_max_trials )
{
    mpm::FosSearchSettings s;
    s.max_trials = 3;
    s.tolerance = 1e-6;
    std::multiset<double> tried;
    const auto r = searchWithAnswer( s, 1.5, &tried );
    EXPECT_FALSE( r.found );
    EXPECT_EQ( r.status, "too_many_trials" );
    EXPECT_EQ( tried.size(), 3u );
}

//---------------------------------------------------------------------------//
TEST( FosCriterion, verdicts_from_the_numbers )
{
    // The defaults: limit 1 m; creep limit 1 mm a quarter with E_kin above
    // 1e-5 of its peak.
    const mpm::FosCriterion c;
    ASSERT_EQ( c.displacement_limit_m, 1.0 );
    ASSERT_EQ( c.creep_limit_m, 0.001 );
    ASSERT_EQ( c.energy_ratio, 1.0e-5 );
    mpm::FosTrialRecord r;
    // Came to rest.
    r.u_max_m = 0.05;
    r.u_three_quarters_m = 0.0499;
    r.ke_ratio = 1.0e-4;
    mpm::judgeTrial( c, r );
    EXPECT_FALSE( r.fails );
    EXPECT_EQ( r.reason, "settled" );
    EXPECT_NEAR( r.last_quarter_m, 1e-4, 1e-12 );
    // Still moving: 3 mm in the last quarter, E_kin at 1e-4 of its peak
    // (Griffiths-Lane's slope at 0.5 m cells, F = 1.375).
    r.u_max_m = 0.103;
    r.u_three_quarters_m = 0.1;
    mpm::judgeTrial( c, r );
    EXPECT_TRUE( r.fails );
    EXPECT_EQ( r.reason, "still_moving" );
    // The same growth with E_kin at 1e-7 of its peak: a residual drift.
    r.ke_ratio = 1.0e-7;
    mpm::judgeTrial( c, r );
    EXPECT_FALSE( r.fails );
    EXPECT_EQ( r.reason, "settled" );
    // E_kin still high, but 0.5 mm a quarter: creep below the limit.
    r.ke_ratio = 0.1;
    r.u_max_m = 0.0015;
    r.u_three_quarters_m = 0.001;
    mpm::judgeTrial( c, r );
    EXPECT_FALSE( r.fails );
    // Beyond the limit.
    r.u_max_m = 1.5;
    r.u_three_quarters_m = 1.5;
    mpm::judgeTrial( c, r );
    EXPECT_TRUE( r.fails );
    EXPECT_EQ( r.reason, "displacement_limit" );
    // The run stopped.
    r.u_max_m = 0.0;
    r.error = "point 3 left the grid";
    mpm::judgeTrial( c, r );
    EXPECT_TRUE( r.fails );
    EXPECT_EQ( r.reason, "run_stopped" );

    const mpm::FosCriterion twice = c.scaled( 2.0 );
    EXPECT_DOUBLE_EQ( twice.displacement_limit_m, 2.0 );
    EXPECT_DOUBLE_EQ( twice.creep_limit_m, 0.002 );
    EXPECT_DOUBLE_EQ( twice.energy_ratio, 2.0e-5 );
    EXPECT_DOUBLE_EQ( twice.damping, c.damping );
    EXPECT_DOUBLE_EQ( twice.periods, c.periods );
}

TEST( FosCriterion, strength_reduction )
{
    const double deg = std::acos( -1.0 ) / 180.0;
    mpm::MaterialConfig m;
    m.model = mpm::ModelType::MohrCoulomb;
    m.cohesion_peak_pa = 20e3;
    m.cohesion_residual_pa = 2e3;
    m.softening_modulus_pa = -250e3;
    m.friction_angle_deg = 30.0;
    m.dilation_angle_deg = 10.0;
    m.tensile_strength_pa = 5e3;
    m.youngs_modulus_pa = 1e7;
    const mpm::MaterialConfig r = mpm::reducedStrength( m, 1.6 );
    EXPECT_DOUBLE_EQ( r.cohesion_peak_pa, 12.5e3 );
    EXPECT_DOUBLE_EQ( r.cohesion_residual_pa, 1.25e3 );
    EXPECT_DOUBLE_EQ( r.softening_modulus_pa, -156.25e3 );
    EXPECT_DOUBLE_EQ( r.tensile_strength_pa, 3.125e3 );
    EXPECT_NEAR( std::tan( r.friction_angle_deg * deg ),
                 std::tan( 30.0 * deg ) / 1.6, 1e-14 );
    EXPECT_NEAR( std::tan( r.dilation_angle_deg * deg ),
                 std::tan( 10.0 * deg ) / 1.6, 1e-14 );
    EXPECT_LE( r.dilation_angle_deg, r.friction_angle_deg );
    EXPECT_DOUBLE_EQ( r.youngs_modulus_pa, m.youngs_modulus_pa );
    // The residual plastic strain (c_r - c0) / H is kept.
    EXPECT_DOUBLE_EQ( ( r.cohesion_residual_pa - r.cohesion_peak_pa ) /
                          r.softening_modulus_pa,
                      ( m.cohesion_residual_pa - m.cohesion_peak_pa ) /
                          m.softening_modulus_pa );
    // No cut-off stays none; an elastic material is not touched.
    m.tensile_strength_pa = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(
        std::isinf( mpm::reducedStrength( m, 2.0 ).tensile_strength_pa ) );
    m.model = mpm::ModelType::LinearElastic;
    EXPECT_DOUBLE_EQ( mpm::reducedStrength( m, 2.0 ).cohesion_peak_pa, 20e3 );
}

TEST( FosCriterion,
      trial_stage_holds_and_locks_the_water_and_drops_the_rain_and_k0 )
{
    mpm::StageConfig base;
    base.type = mpm::StageType::QuasiStatic;
    base.damping = 0.1;
    base.inflows.resize( 2 );
    base.pore_pressures.resize( 1 );
    base.static_stop.static_speed_m_per_s = 0.01;
    base.initial_stress_k0 = 0.6;
    mpm::MaterialConfig m;
    m.model = mpm::ModelType::MohrCoulomb;
    m.cohesion_peak_pa = 10e3;
    m.permeability_m2 = 4.5e-9;
    base.materials = { m };
    const mpm::StageConfig wet = mpm::fosTrialStage( base, true, 2.0, 0.7 );
    EXPECT_EQ( wet.type, mpm::StageType::Dynamic );
    EXPECT_DOUBLE_EQ( wet.damping, 0.7 );
    EXPECT_TRUE( wet.inflows.empty() );
    EXPECT_FALSE( wet.static_stop.enabled() );
    EXPECT_EQ( wet.initial_stress_k0, 0.0 ); // from the saved stress
    ASSERT_EQ( wet.pore_pressures.size(), 1u );
    EXPECT_TRUE( wet.pore_pressures[0].hold_initial );
    EXPECT_EQ( wet.pore_pressures[0].points.kind,
               mpm::PointSelection::Kind::All );
    EXPECT_DOUBLE_EQ( wet.materials[0].cohesion_peak_pa, 5e3 );
    // The water is locked to the skeleton (no flow through the held p_w).
    EXPECT_EQ( wet.materials[0].permeability_m2, 0.0 );
    const mpm::StageConfig dry = mpm::fosTrialStage( base, false, 2.0, 0.7 );
    EXPECT_TRUE( dry.pore_pressures.empty() );
    EXPECT_DOUBLE_EQ( dry.materials[0].permeability_m2, 4.5e-9 );
}

//---------------------------------------------------------------------------//
// The trials use B-bar unless the case sets solver.bbar, and the run goes on
// with its own setting afterwards.
TEST( FosTrialBbar, on_unless_the_case_sets_it )
{
    mpm::SolverConfig run; // the run: no B-bar
    mpm::SolverConfig case_solver;
    {
        const mpm::BbarForTrial trial( run, case_solver ); // key absent
        EXPECT_TRUE( run.bbar );
    }
    EXPECT_FALSE( run.bbar );
    case_solver.bbar_given = true; // solver.bbar = false in the case
    {
        const mpm::BbarForTrial trial( run, case_solver );
        EXPECT_FALSE( run.bbar );
    }
    run.bbar = case_solver.bbar = true; // solver.bbar = true
    {
        const mpm::BbarForTrial trial( run, case_solver );
        EXPECT_TRUE( run.bbar );
    }
    EXPECT_TRUE( run.bbar );
}
