#ifndef MPM_CELL_EQUILIBRIUM_HPP
#define MPM_CELL_EQUILIBRIUM_HPP

#include <mpm_cell_point_lists.hpp>
#include <mpm_device_type.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_pore_pressure.hpp>
#include <mpm_timestep.hpp>
#include <mpm_water_views.hpp>
#include <physics/mpm_cell_pressure_slope.hpp>
#include <physics/mpm_grid_geometry.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_two_phase.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Each cell's mean p_w and point centre over all its points (the
  prescribed ones too), then its pressure slope along x and y from its face
  neighbours with points (physics::limitedPressureSlope; centres closer
  than h/4 along the direction give no difference) and the range its
  profile may span: its own and its neighbours' means, widened by the
  profile's reach h/2 |s_d| along a direction without a neighbour on one
  side (a boundary: the profile extrapolates there).
*/
template <class ExecSpace>
void cellPressureSlopes( const ExecSpace& exec_space,
                         const ParticleViews<ExecSpace>& pv,
                         const WaterParticleViews<ExecSpace>& wv,
                         const physics::GridGeometry& grid,
                         const CellPointLists<ExecSpace>& lists )
{
    const auto occupied = unmanaged( lists.occupied );
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto offset_c = unmanaged( lists.offset_c );
    const auto points_c = unmanaged( lists.points_c );
    const auto level_c = unmanaged( lists.level_c );
    const auto centre_c = unmanaged( lists.centre_c );
    const auto slope_c = unmanaged( lists.slope_c );
    const auto bound_c = unmanaged( lists.bound_c );
    const int nx = grid.nx, ny = grid.ny;
    const double min_distance = 0.25 * grid.h;
    const double reach = 0.5 * grid.h;

    Kokkos::parallel_for(
        "mpm::cell_pressure_levels", occupiedCellPolicy( exec_space, lists ),
        KOKKOS_LAMBDA( const int k ) {
            const int c = occupied( k );
            const int begin = offset_c( c );
            const int count = offset_c( c + 1 ) - begin;
            double p = 0.0, x = 0.0, y = 0.0;
            for ( int a = begin; a < begin + count; ++a )
            {
                const int q = points_c( a );
                p += water_points.p_w_p( q );
                x += points.x_p( q, 0 );
                y += points.x_p( q, 1 );
            }
            const double inv = count > 0 ? 1.0 / count : 0.0;
            level_c( c ) = p * inv;
            centre_c( c, 0 ) = x * inv;
            centre_c( c, 1 ) = y * inv;
        } );
    Kokkos::parallel_for(
        "mpm::cell_pressure_slopes", occupiedCellPolicy( exec_space, lists ),
        KOKKOS_LAMBDA( const int k ) {
            const int c = occupied( k );
            slope_c( c, 0 ) = 0.0;
            slope_c( c, 1 ) = 0.0;
            bound_c( c, 0 ) = level_c( c );
            bound_c( c, 1 ) = level_c( c );
            if ( offset_c( c + 1 ) == offset_c( c ) )
                return;
            double extension = 0.0; // towards sides without a neighbour
            const int index[2] = { c / ny, c % ny };
            const int extent[2] = { nx, ny };
            const int stride[2] = { ny, 1 };
            for ( int d = 0; d < 2; ++d )
            {
                bool has[2] = { false, false };
                double difference[2] = { 0.0, 0.0 };
                for ( int side = 0; side < 2; ++side )
                {
                    const int step = side == 0 ? -1 : 1;
                    const int i = index[d] + step;
                    if ( i < 0 || i >= extent[d] )
                        continue;
                    const int n = c + step * stride[d];
                    if ( offset_c( n + 1 ) == offset_c( n ) )
                        continue;
                    const double distance = centre_c( n, d ) - centre_c( c, d );
                    if ( !( step * distance > min_distance ) )
                        continue;
                    has[side] = true;
                    difference[side] =
                        ( level_c( n ) - level_c( c ) ) / distance;
                    bound_c( c, 0 ) = level_c( n ) < bound_c( c, 0 )
                                          ? level_c( n )
                                          : bound_c( c, 0 );
                    bound_c( c, 1 ) = level_c( n ) > bound_c( c, 1 )
                                          ? level_c( n )
                                          : bound_c( c, 1 );
                }
                slope_c( c, d ) = physics::limitedPressureSlope(
                    has[0], difference[0], has[1], difference[1] );
                if ( !has[0] || !has[1] )
                    extension +=
                        reach * Kokkos::Experimental::fabs( slope_c( c, d ) );
            }
            bound_c( c, 0 ) -= extension;
            bound_c( c, 1 ) += extension;
        } );
}

//---------------------------------------------------------------------------//
//! What cellWaterEquilibrium returns: the CFL limit of the points it
//! listed, after its update, and how many it listed.
struct CellEquilibriumLimit
{
    WaveSpeedLimit limit;
    int listed;
};

//---------------------------------------------------------------------------//
/*!
  \brief physics::CellWaterEquilibrium on every cell (points at their new
  positions, after the step's point update): lists the points of each cell,
  takes each cell's pressure slope from its neighbours (linear_profile;
  else a uniform pressure), solves each cell's level and sets the profile's
  pressure, with the retention state, on the cell's points whose p_w is not
  prescribed (a cell whose points already lie on it is left as it is); the
  water that moves between them carries its seepage velocity (the takers'
  v_w - v_s becomes the mass-weighted mean). Returns the CFL limit of the
  listed points' new state for the scheme's fastest wave `wave_speed`
  (TwoPhaseWaveSpeed, or the skeleton's DryWaveSpeed) and how many were
  listed: the step's cached limit, taken before, would be stale.
*/
template <class ExecSpace, class WaveSpeed>
CellEquilibriumLimit cellWaterEquilibrium(
    const ExecSpace& exec_space, const ParticleViews<ExecSpace>& pv,
    const WaterParticleViews<ExecSpace>& wv, const physics::GridGeometry& grid,
    const physics::MaterialTable& materials, const physics::WaterParams& water,
    const bool saturated, const bool linear_profile,
    CellPointLists<ExecSpace>& lists, const WaveSpeed& wave_speed )
{
    listCellPoints( exec_space, pv, wv, grid, lists );
    if ( linear_profile )
        cellPressureSlopes( exec_space, pv, wv, grid, lists );
    else
        Kokkos::deep_copy( exec_space, lists.slope_c, 0.0 );

    const auto occupied = unmanaged( lists.occupied );
    const auto points = unmanaged( pv );
    const auto water_points = unmanaged( wv );
    const auto offset_c = unmanaged( lists.offset_c );
    const auto points_c = unmanaged( lists.points_c );
    const auto centre_c = unmanaged( lists.centre_c );
    const auto slope_c = unmanaged( lists.slope_c );
    const auto bound_c = unmanaged( lists.bound_c );
    const auto change_p = unmanaged( lists.change_p );
    const double cell_size = grid.h;
    const physics::CellWaterEquilibrium equilibrium{ water.bulk_modulus };

    CellEquilibriumLimit result{ { 0.0, 0.0 }, 0 };
    Kokkos::parallel_reduce(
        "mpm::cell_equilibrium_solve", occupiedCellPolicy( exec_space, lists ),
        KOKKOS_LAMBDA( const int k, double& dt_min, double& c_max,
                       int& listed ) {
            const int c = occupied( k );
            const auto solve_cell = [&]()
            {
                const int begin = offset_c( c );
                int end = begin; // the free points come first
                while ( end < offset_c( c + 1 ) &&
                        water_points.p_w_condition_p( points_c( end ) ) < 0 )
                    ++end;
                if ( end - begin < 2 )
                    return;
                // The slope's share: halved until the profile stays within the
                // cell's range (the retention law is not linear: where a front
                // crosses the cell, the level that holds the water can sink
                // the dry side's points below every suction around them).
                double share = linear_profile ? 1.0 : 0.0;
                const auto profile = [&]( const int p )
                {
                    return share * ( slope_c( c, 0 ) * ( points.x_p( p, 0 ) -
                                                         centre_c( c, 0 ) ) +
                                     slope_c( c, 1 ) * ( points.x_p( p, 1 ) -
                                                         centre_c( c, 1 ) ) );
                };
                const auto point = [&]( const int a )
                {
                    const int p = points_c( begin + a );
                    return physics::CellWaterEquilibrium::Point{
                        points.vol_p( p ) * water_points.n_p( p ),
                        water_points.S_p( p ), water_points.p_w_p( p ),
                        profile( p ),
                        &materials[points.material_p( p )].retention };
                };
                bool changed = false;
                double level = equilibrium.solve( end - begin, point, changed );
                for ( int attempt = 0; attempt < 4 && share > 0.0; ++attempt )
                {
                    bool inside = true;
                    const double margin =
                        1.0e-9 * ( bound_c( c, 1 ) - bound_c( c, 0 ) ) + 1.0e-6;
                    for ( int a = begin; a < end; ++a )
                    {
                        const double p_w = level + profile( points_c( a ) );
                        inside = inside && p_w >= bound_c( c, 0 ) - margin &&
                                 p_w <= bound_c( c, 1 ) + margin;
                    }
                    if ( inside )
                        break;
                    share = attempt < 2 ? 0.5 * share : 0.0;
                    level = equilibrium.solve( end - begin, point, changed );
                }
                if ( !changed )
                    return;
                if ( saturated )
                {
                    for ( int a = begin; a < end; ++a )
                    {
                        const int p = points_c( a );
                        water_points.p_w_p( p ) = level + profile( p );
                    }
                    return;
                }
                // The new state of each point and the water it gives or takes.
                double given = 0.0, given_v[2] = { 0.0, 0.0 };
                for ( int a = begin; a < end; ++a )
                {
                    const int p = points_c( a );
                    const double p_w = level + profile( p );
                    const physics::RetentionState state =
                        RetentionAt{
                            materials[points.material_p( p )].retention }
                            .state( p_w );
                    const double change = points.vol_p( p ) *
                                          water_points.n_p( p ) *
                                          ( state.S - water_points.S_p( p ) );
                    change_p( p ) = change;
                    if ( change < 0.0 )
                    {
                        given -= change;
                        given_v[0] -= change * ( water_points.v_w_p( p, 0 ) -
                                                 points.v_p( p, 0 ) );
                        given_v[1] -= change * ( water_points.v_w_p( p, 1 ) -
                                                 points.v_p( p, 1 ) );
                    }
                    water_points.p_w_p( p ) = p_w;
                    water_points.S_p( p ) = state.S;
                    water_points.dS_dp_p( p ) = state.dS_dp;
                    water_points.k_rel_p( p ) = state.k_rel;
                }
                // The water that moves between the points carries its seepage
                // velocity w = v_w - v_s: the points that give water keep
                // theirs, those that take it get the mass-weighted mean with
                // the given water's (water locked to the solid stays locked).
                if ( !( given > 0.0 ) )
                    return;
                for ( int a = begin; a < end; ++a )
                {
                    const int p = points_c( a );
                    const double change = change_p( p );
                    if ( !( change > 0.0 ) )
                        continue;
                    const double after = points.vol_p( p ) *
                                         water_points.n_p( p ) *
                                         water_points.S_p( p );
                    for ( int d = 0; d < 2; ++d )
                        water_points.v_w_p( p, d ) =
                            points.v_p( p, d ) +
                            ( ( after - change ) *
                                  ( water_points.v_w_p( p, d ) -
                                    points.v_p( p, d ) ) +
                              change * given_v[d] / given ) /
                                after;
                }
            };
            solve_cell();
            // The CFL limit of the cell's points in their new state.
            for ( int a = offset_c( c ); a < offset_c( c + 1 ); ++a )
            {
                const int p = points_c( a );
                addPointLimit( wave_speed, p, materials[points.material_p( p )],
                               cell_size, dt_min, c_max );
                ++listed;
            }
        },
        Kokkos::Min<double>( result.limit.dt_limit ),
        Kokkos::Max<double>( result.limit.max_wave_speed ),
        Kokkos::Sum<int>( result.listed ) );
    return result;
}

} // namespace mpm

#endif // MPM_CELL_EQUILIBRIUM_HPP
