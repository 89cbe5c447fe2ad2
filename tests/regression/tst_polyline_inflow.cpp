// Rain on a polyline ([[stages.inflows]] where = "polyline"): the water
// that enters equals flux x length x time, and it enters the cells the
// line passes through, each its own piece's share.
#include <mpm_test_backends.hpp>

#include <io/mpm_case_reader.hpp>
#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace
{
MPM_TEST_BACKEND_SUITE( PolylineInflow );

//! Collects the warnings of a run.
class WarningRecorder : public mpm::RunObserver
{
  public:
    void onWarning( const std::string& text ) override
    {
        warnings.push_back( text );
    }
    std::vector<std::string> warnings;
};

const double flux = 1.0e-3;    // m/s
const double duration = 0.05;  // s
const double bulk = 2.2e9;     // K_w, Pa
const double porosity = 0.3;   // n
const double cell_size = 0.25; // m

/*!
  A sealed box: soil 2 m wide and 1 m deep in a 2 m x 1.5 m grid of
  0.25 m cells, every node fixed (a fixed, impermeable below_polyline
  boundary along the grid's top: neither phase moves), no gravity, at
  p_w = `p0`. Rain of `flux` for `duration` on the polyline
  (0.1, 0.6) - (0.6, 0.6) - (0.6, 0.5) - (1.0, 0.5): 0.5 m at y = 0.6,
  0.1 m down, 0.4 m along the grid line y = 0.5; measured as `measure`.
  A second inflow on a line above the soil feeds nothing (a warning).
*/
std::string sealedBoxCase( const std::string& analysis,
                           const std::string& measure, const double p0 )
{
    char numbers[256];
    std::snprintf( numbers, sizeof( numbers ),
                   "flux_m_per_s = %.17g\nmeasured_on = \"%s\"\n", flux,
                   measure.c_str() );
    const std::string retention = analysis == "unsaturated" ? R"(
[materials.retention]
model = "van_genuchten"
alpha_per_pa = 4.4e-4
n = 3.04
residual_saturation = 0.23
)"
                                                            : "";
    return R"(
[case]
name = "sealed_box"
analysis = ")" +
           analysis + R"("
[water]
bulk_modulus_pa = 2.2e9
[grid]
origin_m = [0.0, 0.0]
cell_size_m = 0.25
cells = [8, 6]
[[materials]]
name = "soil"
model = "linear_elastic"
solid_density_kg_per_m3 = 2700.0
porosity = 0.3
permeability_m2 = 1.0e-12
youngs_modulus_pa = 1.0e7
poisson_ratio = 0.3
)" + retention +
           R"(
[[bodies]]
material = "soil"
polygon_m = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]
initial_pore_pressure_pa = )" +
           std::to_string( p0 ) + R"(
[[boundaries]]
where = "below_polyline"
condition = "fixed"
polyline_m = [[0.0, 1.5], [2.0, 1.5]]
[solver]
base_cell_completion = false
[[stages]]
name = "rain"
type = "dynamic"
gravity_m_per_s2 = [0.0, 0.0]
duration_s = 0.05
[[stages.inflows]]
where = "polyline"
polyline_m = [[0.1, 0.6], [0.6, 0.6], [0.6, 0.5], [1.0, 0.5]]
ponding = false
)" + numbers +
           R"(
[[stages.inflows]]
where = "polyline"
polyline_m = [[0.1, 1.3], [1.9, 1.3]]
flux_m_per_s = 1.0
ponding = false
)";
}

//! Flat index i * 6 + j of the cell of point p.
int cellOf( const mpm::HostSnapshot& snap, const int p )
{
    return static_cast<int>( std::floor( snap.x[2 * p] / cell_size ) ) * 6 +
           static_cast<int>( std::floor( snap.x[2 * p + 1] / cell_size ) );
}

/*!
  Saturated: the water gained per cell, the change of its mass over rho_w,
  n V (1 + p_w / K_w), summed as the change of n V (zero here: nothing
  moves) plus that of n V p_w / K_w (without subtracting the large n V).
*/
std::map<int, double> gainedWater( const mpm::HostSnapshot& before,
                                   const mpm::HostSnapshot& after )
{
    std::map<int, double> water;
    for ( int p = 0; p < after.num_points; ++p )
    {
        const double a0 = before.n[p] * before.vol[p];
        const double a1 = after.n[p] * after.vol[p];
        water[cellOf( after, p )] +=
            ( a1 - a0 ) + ( a1 * after.p_w[p] - a0 * before.p_w[p] ) / bulk;
    }
    return water;
}

//---------------------------------------------------------------------------//
// Saturated, where the stored water is exactly n V (1 + p_w / K_w): the
// water gained equals flux x length x time to round-off, along the line
// (length 1.0 m) and on the horizontal (0.9 m); each cell gains its own
// piece's share (lengths measured by hand, a piece on the grid line y = 0.5
// halved between the cells on its sides) and every other cell nothing.
TYPED_TEST( PolylineInflow,
            adds_flux_times_length_times_time_where_the_line_is )
{
    const auto cell = []( const int i, const int j ) { return i * 6 + j; };
    for ( const std::string measure : { "along_line", "horizontal" } )
    {
        SCOPED_TRACE( measure );
        const bool along = measure == "along_line";
        const auto config = mpm::parseCase(
            sealedBoxCase( "saturated", measure, 0.0 ), "sealed_box.toml" );
        const double length = along ? 1.0 : 0.9;
        EXPECT_NEAR( config.stages[0].inflows[0].length_m, length, 1.0e-15 );
        mpm::Simulation<TypeParam> sim( config );
        const auto before = mpm::hostSnapshot( sim );
        WarningRecorder observer;
        mpm::runStages( sim, config, observer );
        const auto after = mpm::hostSnapshot( sim );

        // The inflow above the soil fed nothing, and said so.
        ASSERT_EQ( observer.warnings.size(), 1u );
        EXPECT_EQ( observer.warnings[0],
                   "key 'stages[0].inflows[1].where': selects no material "
                   "point at the stage start" );
        // Nothing moved.
        for ( std::size_t k = 0; k < after.v.size(); ++k )
            ASSERT_EQ( after.v[k], 0.0 );

        const auto water = gainedWater( before, after );
        double gained = 0.0;
        for ( const auto& cell_gain : water )
            gained += cell_gain.second;
        const double expected = flux * length * duration;
        const double relative = std::abs( gained - expected ) / expected;
        std::printf( "[ polyline ] %s: water gained %.15e m^3/m, q L t "
                     "%.15e, relative error %.2e\n",
                     measure.c_str(), gained, expected, relative );
        EXPECT_LT( relative, 1.0e-11 );

        // Per cell: 0.15 / 0.25 / 0.1 m at y = 0.6, 0.1 m down in (2, 2),
        // 0.15 and 0.25 m along y = 0.5 halved between rows 1 and 2.
        const double down = along ? 0.1 : 0.0;
        const std::map<int, double> pieces = {
            { cell( 0, 2 ), 0.15 },
            { cell( 1, 2 ), 0.25 },
            { cell( 2, 2 ), 0.1 + down + 0.075 },
            { cell( 2, 1 ), 0.075 },
            { cell( 3, 1 ), 0.125 },
            { cell( 3, 2 ), 0.125 } };
        double worst = 0.0; // largest error of a cell, relative to q L t
        for ( const auto& [c, w] : water )
        {
            const auto it = pieces.find( c );
            const double share = it == pieces.end() ? 0.0 : it->second;
            worst = std::max( worst, std::abs( w - flux * share * duration ) /
                                         expected );
            EXPECT_NEAR( w, flux * share * duration, 1.0e-12 * expected )
                << "cell (" << c / 6 << ", " << c % 6 << ")";
        }
        std::printf( "[ polyline ] %s: largest cell error %.2e of q L t\n",
                     measure.c_str(), worst );
    }
}

//---------------------------------------------------------------------------//
// Unsaturated (van Genuchten, 5 kPa suction): the water volume n S V
// gained equals flux x length x time within the compressibility of the
// water (the part stored as n S dp / K_w, a fraction S / (K_w dS/dp) of
// about 1e-5 here).
TYPED_TEST( PolylineInflow, unsaturated_soil_takes_the_rain_of_the_line )
{
    const auto config =
        mpm::parseCase( sealedBoxCase( "unsaturated", "along_line", -5.0e3 ),
                        "sealed_box.toml" );
    mpm::Simulation<TypeParam> sim( config );
    const auto before = mpm::hostSnapshot( sim );
    mpm::RunObserver observer;
    mpm::runStages( sim, config, observer );
    const auto after = mpm::hostSnapshot( sim );
    double gained = 0.0;
    for ( int p = 0; p < after.num_points; ++p )
        gained += after.n[p] * after.vol[p] * ( after.S[p] - before.S[p] );
    const double expected = flux * 1.0 * duration;
    const double relative = std::abs( gained - expected ) / expected;
    std::printf( "[ polyline ] unsaturated: n S V gained %.15e m^3/m, q L t "
                 "%.15e, relative error %.2e\n",
                 gained, expected, relative );
    EXPECT_LT( relative, 2.0e-5 );
    EXPECT_LT( gained, expected ); // the rest is in the compression
}

} // namespace
