#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

#include <map>

namespace
{
MPM_TEST_BACKEND_SUITE( BBar );

/*!
  Point-level checkerboard of p_w: RMS over points of p_w minus the mean of
  its cell, over the RMS of p_w (the oscillation between the 2 x 2 points
  of a cell).
*/
double intraCell( const mpm::HostSnapshot& snap, const double h )
{
    std::map<std::pair<int, int>, std::pair<double, int>> cells;
    auto cellOf = [&]( int p )
    {
        return std::make_pair( static_cast<int>( snap.x[2 * p] / h ),
                               static_cast<int>( snap.x[2 * p + 1] / h ) );
    };
    for ( int p = 0; p < snap.num_points; ++p )
    {
        auto& c = cells[cellOf( p )];
        c.first += snap.p_w[p];
        c.second += 1;
    }
    double diff2 = 0.0, ref2 = 0.0;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        const auto& c = cells[cellOf( p )];
        const double d = snap.p_w[p] - c.first / c.second;
        diff2 += d * d;
        ref2 += snap.p_w[p] * snap.p_w[p];
    }
    return std::sqrt( diff2 / ref2 );
}

/*!
  Checkerboard metric of p_w: the RMS over cells of the difference between
  a cell's mean p_w and the mean of its (up to 4) edge neighbours, over the
  RMS of the cell means. A smooth field gives O(h^2) differences, a
  checkerboard twice its amplitude.
*/
double checkerboard( const mpm::HostSnapshot& snap, const double h )
{
    std::map<std::pair<int, int>, std::pair<double, int>> cells;
    for ( int p = 0; p < snap.num_points; ++p )
    {
        auto& c = cells[{ static_cast<int>( snap.x[2 * p] / h ),
                          static_cast<int>( snap.x[2 * p + 1] / h ) }];
        c.first += snap.p_w[p];
        c.second += 1;
    }
    double diff2 = 0.0, ref2 = 0.0;
    int count = 0;
    for ( const auto& [ij, c] : cells )
    {
        const double mean = c.first / c.second;
        double neighbours = 0.0;
        int n = 0;
        for ( const auto& d :
              { std::make_pair( 1, 0 ), std::make_pair( -1, 0 ),
                std::make_pair( 0, 1 ), std::make_pair( 0, -1 ) } )
        {
            const auto it =
                cells.find( { ij.first + d.first, ij.second + d.second } );
            if ( it == cells.end() )
                continue;
            neighbours += it->second.first / it->second.second;
            ++n;
        }
        if ( n < 4 )
            continue; // interior cells only
        diff2 += ( mean - neighbours / n ) * ( mean - neighbours / n );
        ref2 += mean * mean;
        ++count;
    }
    return count > 0 ? std::sqrt( diff2 / ref2 ) : 0.0;
}

/*!
  Undrained strip footing: a saturated block 2 m x 1 m (0.1 m cells, 2 x 2
  points, k = 1e-14 m^2 so nothing drains during the 0.3 s run, nu = 0.3)
  on a fixed base with rollers, loaded on the left half of its top by
  20 kPa ramped over 0.05 s, with damping to a quasi-static state.
*/
mpm::CaseConfig footingCase( const bool bbar, const bool cell_equilibrium )
{
    mpm::StageConfig stage = mpm_test::stageConfig(
        "footing", mpm::StageType::Dynamic, 0.3, 0.0, 0.3 );
    auto c = mpm_test::columnCase(
        1.0, 0.1,
        mpm_test::saturatedMaterial( 1.0e7, 0.3, 2650.0, 0.3, 1.0e-14 ),
        stage );
    c.analysis = mpm::AnalysisType::Saturated;
    c.grid.cells = { 20, 12 };
    c.bodies[0].polygon_m = {
        { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 1.0 }, { 0.0, 1.0 } };
    mpm::PointLoad load;
    load.points.box_m = { mpm::Point2{ 0.0, 0.95 }, mpm::Point2{ 1.0, 1.0 } };
    load.traction_pa = { 0.0, -2.0e4 };
    load.length_m = 1.0;
    load.time_function = { { 0.0, 0.0 }, { 0.05, 1.0 } };
    c.stages[0].loads = { load };
    c.solver.bbar = bbar;
    c.solver.cell_equilibrium = cell_equilibrium;
    return c;
}

//---------------------------------------------------------------------------//
// B-bar (cell-averaged volumetric rates of both phases) removes the
// point-to-point checkerboard of p_w that the near-incompressible undrained
// response produces with point-wise divergences.
TYPED_TEST( BBar, reduces_pore_pressure_checkerboard )
{
    // Point-wise p_w (no stabilisation), B-bar, the cell water equilibrium
    // (the default, physics::CellWaterEquilibrium, with its pressure slope).
    const bool bbar[3] = { false, true, false };
    const bool equilibrium[3] = { false, false, true };
    double metric[3], intra[3];
    for ( int v = 0; v < 3; ++v )
    {
        auto config = footingCase( bbar[v], equilibrium[v] );
        mpm::Simulation<TypeParam> sim( config );
        mpm::RunObserver observer;
        mpm::runStages( sim, config, observer );
        const auto snap = mpm::hostSnapshot( sim );
        metric[v] = checkerboard( snap, 0.1 );
        intra[v] = intraCell( snap, 0.1 );
    }
    std::printf( "p_w checkerboard: cells %.4f / %.4f / %.4f, points in a "
                 "cell %.4f / %.4f / %.4f (point-wise / B-bar / cell "
                 "equilibrium)\n",
                 metric[0], metric[1], metric[2], intra[0], intra[1],
                 intra[2] );
    // Point-wise, the points of a cell differ by as much as p_w itself;
    // with B-bar they share the cell's volumetric
    // rates and p_w; the cell equilibrium leaves the profile of the slope
    // its neighbours give (3.5 % of the point-wise spread).
    EXPECT_GT( intra[0], 0.2 );
    EXPECT_LT( intra[1], 0.01 * intra[0] );
    EXPECT_LT( intra[2], 0.1 * intra[0] );
    // Between cells the field is smooth (the metric is the curvature of
    // the footing's pressure bulb).
    EXPECT_LT( metric[1], 0.05 );
    EXPECT_LT( metric[2], 0.05 );
}

} // namespace
