// The seepage scheme (solver.scheme = "seepage") against Srivastava & Yeh
// (1991) in its own units: K_s = 1 cm/h, hours of rain.
#include <mpm_gardner_infiltration.hpp>
#include <mpm_test_backends.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
template <class ExecSpace>
class SeepageInfiltration : public ::testing::Test
{
};
TYPED_TEST_SUITE( SeepageInfiltration, mpm_test::Backends,
                  mpm_test::BackendName );

// Srivastava & Yeh's homogeneous column: K_s = 1 cm/h, alpha = 0.1 /cm,
// 100 cm on a water table, theta_s = 0.40, theta_r = 0.06; the surface flux
// steps from 0.1 K_s (the steady start) to 0.9 K_s.
constexpr double alpha = 10.0; // 1/m of head
constexpr double height = 1.0; // m
constexpr double porosity = 0.40;
constexpr double residual_saturation = 0.15; // theta_r / theta_s
constexpr double theta_range = porosity * ( 1.0 - residual_saturation );
constexpr double rho_w_g = 1000.0 * 9.81;
constexpr double K_s = 0.01 / 3600.0; // m/s
constexpr double viscosity = 1.0e-3;
constexpr double q_A = 0.1, q_B = 0.9; // K_s
constexpr double hour = 3600.0;

//! The steady pressure head profile under q_A: K/K_s = q_A + (1 - q_A)
//! exp(-alpha z), p_w = rho_w g ln(K/K_s) / alpha, as 41 pairs.
std::string steadyStartProfile()
{
    std::string pairs;
    for ( int k = 0; k <= 40; ++k )
    {
        const double z = height * k / 40.0;
        const double K = q_A + ( 1.0 - q_A ) * std::exp( -alpha * z );
        char pair[96];
        std::snprintf( pair, sizeof pair, "%s[%.17g, %.17g]", k ? ", " : "", z,
                       rho_w_g * std::log( K ) / alpha );
        pairs += pair;
    }
    return "[" + pairs + "]";
}

/*!
  The column (one cell wide, `cells` high, stiff: the exact solution's soil
  is rigid) on a drained base, its top the grid's top edge with the rain as
  an edge flux, started from the steady profile of q_A, then `hours` of rain
  at `rain` (units of K_s) with snapshots landing on the whole hours;
  `solver` the [solver] table's keys but the scheme, `scheme`.
*/
std::string column( const int cells, const double hours,
                    const std::string& solver, const double rain,
                    const std::string& scheme )
{
    const double h = height / cells;
    char text[2048];
    std::snprintf(
        text, sizeof text,
        "[case]\nname = \"sy_column\"\nanalysis = \"unsaturated\"\n"
        "[grid]\norigin_m = [0.0, 0.0]\ncell_size_m = %.17g\ncells = [1, %d]\n"
        "[[materials]]\nname = \"soil\"\nmodel = \"linear_elastic\"\n"
        "solid_density_kg_per_m3 = 2700.0\nporosity = %.17g\n"
        "permeability_m2 = %.17g\nyoungs_modulus_pa = 1.0e8\n"
        "poisson_ratio = 0.0\n"
        "[materials.retention]\nmodel = \"gardner\"\nalpha_per_m = %.17g\n"
        "residual_saturation = %.17g\n"
        "[[boundaries]]\nwhere = \"left\"\ncondition = \"fix_x\"\n"
        "[[boundaries]]\nwhere = \"right\"\ncondition = \"fix_x\"\n"
        "[[boundaries]]\nwhere = \"bottom\"\ncondition = \"fixed\"\n"
        "hydraulic = \"drained\"\n"
        "[[bodies]]\nmaterial = \"soil\"\n"
        "polygon_m = [[0.0, 0.0], [%.17g, 0.0], [%.17g, %.17g], "
        "[0.0, %.17g]]\n",
        h, cells, porosity, K_s * viscosity / rho_w_g, alpha,
        residual_saturation, h, h, height, height );
    std::string snapshot_times;
    for ( int k = 1; k <= static_cast<int>( hours ); ++k )
        snapshot_times += ( k > 1 ? ", " : "" ) + std::to_string( k * hour );
    char stage[256];
    std::snprintf( stage, sizeof stage,
                   "duration_s = %.17g\n[[stages.inflows]]\nwhere = \"top\"\n"
                   "flux_m_per_s = %.17g\n",
                   hours * hour, rain * K_s );
    return std::string( text ) +
           "initial_pore_pressure_profile = " + steadyStartProfile() +
           "\n[solver]\nscheme = \"" + scheme + "\"\n" + solver +
           "[[stages]]\nname = \"rain\"\ntype = \"dynamic\"\n"
           "gravity_m_per_s2 = [0.0, -9.81]\nsnapshot_times_s = [" +
           snapshot_times + "]\n" + stage;
}

//! The snapshots of the run and their stage times.
class Snapshots : public mpm::RunObserver
{
  public:
    void onSnapshot( const mpm::RunProgress& progress,
                     const mpm::HostSnapshot& snapshot ) override
    {
        times.push_back( progress.stage_time_s );
        snapshots.push_back( snapshot );
    }
    std::vector<double> times;
    std::vector<mpm::HostSnapshot> snapshots;
};

//! What a run gave: the largest |K/K_s - exact| at `hours` of rain over the
//! points below the top cell and over the top cell's, its step count and
//! its largest saturation change.
struct SeepageResult
{
    double below_top = 0.0;
    double top_cell = 0.0;
    long steps = 0;
};

template <class ExecSpace>
SeepageResult errorAt( const int cells, const double hours,
                       const std::string& solver = "", const double rain = q_B,
                       const std::string& scheme = "seepage" )
{
    const auto config = mpm::parseCase(
        column( cells, hours, solver, rain, scheme ), "sy_column" );
    mpm::Simulation<ExecSpace> sim( config );
    Snapshots observer;
    const mpm::RunSummary summary = mpm::runStages( sim, config, observer );
    SeepageResult result;
    result.steps = summary.steps;
    const mpm_test::GardnerInfiltration exact( alpha, height, q_A, rain );
    const double h = height / cells;
    for ( std::size_t k = 0; k < observer.snapshots.size(); ++k )
    {
        if ( std::fabs( observer.times[k] - hours * hour ) > 1.0e-6 )
            continue;
        const mpm::HostSnapshot& snap = observer.snapshots[k];
        const double t_star =
            exact.tStar( observer.times[k], K_s, theta_range );
        for ( int p = 0; p < snap.num_points; ++p )
        {
            const double z = snap.x[2 * p + 1];
            const double K =
                std::min( 1.0, std::exp( alpha * snap.p_w[p] / rho_w_g ) );
            const double error =
                std::fabs( K - exact.relativeConductivity( z, t_star ) );
            double& worst = z > height - h ? result.top_cell : result.below_top;
            worst = std::max( worst, error );
        }
    }
    std::printf( "%s, Srivastava-Yeh in cm/h: %d cells, %.0f h of rain, "
                 "%s: %ld steps, |K/K_s - exact| below the top cell %.4f, "
                 "top cell %.4f\n",
                 scheme.c_str(), cells, hours,
                 solver.empty()
                     ? "default step"
                     : solver.substr( 0, solver.find( '\n' ) ).c_str(),
                 result.steps, result.below_top, result.top_cell );
    return result;
}

// The start is steady: rained on at q_A, the column keeps its profile
// (0.0037 below the top cell after 10 h at 20 cells).
TYPED_TEST( SeepageInfiltration, steady_start_stays_steady )
{
    const SeepageResult steady = errorAt<TypeParam>( 20, 10.0, "", q_A );
    EXPECT_LT( steady.below_top, 0.011 );
}

// 10 and 20 hours of rain at 20 cells (5 cm) with the default step rule:
// below the top cell within 0.0059 and 0.0109 of the exact K/K_s (145 steps
// for the 20 h), where a wave-limited step (~1e-5 s) would take billions.
TYPED_TEST( SeepageInfiltration, conductivity_matches_exact_after_hours )
{
    const SeepageResult ten = errorAt<TypeParam>( 20, 10.0 );
    EXPECT_LT( ten.below_top, 0.019 );
    const SeepageResult twenty = errorAt<TypeParam>( 20, 20.0 );
    EXPECT_LT( twenty.below_top, 0.033 );
    EXPECT_LT( twenty.steps, 400 );
}

// The step rule controls the error in time: at 40 cells (where the grid's
// own error is small) a quarter of the saturation change per step gives
// about a third of the error after 20 h (0.0048 against 0.0147).
TYPED_TEST( SeepageInfiltration, smaller_saturation_change_gives_smaller_error )
{
    const SeepageResult coarse =
        errorAt<TypeParam>( 40, 20.0, "seepage_saturation_change = 0.02\n" );
    const SeepageResult fine =
        errorAt<TypeParam>( 40, 20.0, "seepage_saturation_change = 0.005\n" );
    EXPECT_LT( fine.below_top, 0.5 * coarse.below_top );
    EXPECT_GT( fine.steps, 2 * coarse.steps );
}

// The quasi-static scheme (docs/formulation.md §11) on the same column: the
// seepage scheme's flow with the skeleton's storage, the skeleton relaxed to
// equilibrium after each step. 20 h of rain at 20 cells: below the top cell
// within 0.0108 of the exact K/K_s (the seepage scheme 0.0109), in 144 steps.
TYPED_TEST( SeepageInfiltration, quasi_static_matches_exact_after_hours )
{
    const SeepageResult seepage = errorAt<TypeParam>( 20, 20.0 );
    const SeepageResult quasi_static =
        errorAt<TypeParam>( 20, 20.0, "", q_B, "quasi_static" );
    EXPECT_LT( quasi_static.below_top, 0.033 );
    EXPECT_LT( quasi_static.steps, 400 );
    EXPECT_NEAR( quasi_static.below_top, seepage.below_top, 5.0e-4 );
}

} // namespace
