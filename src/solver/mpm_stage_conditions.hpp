#ifndef MPM_STAGE_CONDITIONS_HPP
#define MPM_STAGE_CONDITIONS_HPP

#include <case/mpm_case_config.hpp>
#include <case/mpm_polyline_cells.hpp>
#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <setup/mpm_conditions.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Prescribed point pore pressures, point loads and water inflows of
  the current stage: which condition each point belongs to (chosen at the
  stage start from the current positions), the p_w held by a hold
  condition, the current values of each condition and which selections
  picked no point.
*/
template <class ExecSpace>
struct StageConditions
{
    using device_type = DeviceType<ExecSpace>;
    //! Current pressure of each pore-pressure condition, Pa.
    Kokkos::View<double*, device_type> prescribed_p_w{ "prescribed_p_w", 0 };
    //! 1 if the pore-pressure condition holds its points' p_w at the stage
    //! start (WaterParticleViews::p_w_held_p), else 0.
    Kokkos::View<int*, device_type> prescribed_hold{ "prescribed_hold", 0 };
    //! Current force on one point of each load group, N.
    LoadForceView<ExecSpace> load_force{ "load_force", 0 };
    //! Current water inflow of each inflow per unit initial point volume
    //! (vol0_p), 1/s.
    Kokkos::View<double*, device_type> inflow_rate{ "inflow_rate", 0 };
    //! 1 if the inflow ponds (caps p_w at 0 on its points), else 0.
    Kokkos::View<int*, device_type> inflow_ponding{ "inflow_ponding", 0 };
    //! Current inward water flux of the inflows on grid edges at each node
    //! (i, j, direction), m/s (volume per area and time); zero elsewhere.
    Kokkos::View<double***, device_type> inflow_flux_i{ "inflow_flux_i", 0, 0,
                                                        0 };
    std::vector<WaterInflow> inflows;
    //! Initial volume (vol0_p) of the points fed, m^3/m.
    std::vector<double> inflow_volumes;
    //! Stage time of the next surface re-detection of the inflows that
    //! follow the surface (1e300 if none does).
    double next_surface_update_s = 1.0e300;
    std::vector<PorePressureCondition> pore_pressures;
    std::vector<PointLoad> loads;
    std::vector<int> load_counts;              //!< points per load
    std::vector<std::vector<int>> load_groups; //!< loads of each group
    //! The stage's point selections that picked no point at its start,
    //! as key paths within the stage ("inflows[0].where").
    std::vector<std::string> empty_selections;

    //! Assigns the stage's conditions to the points.
    void apply( const StageConfig& stage, const ParticleViews<ExecSpace>& pv,
                const WaterParticleViews<ExecSpace>& wv,
                const GridConfig& grid )
    {
        pore_pressures = stage.pore_pressures;
        loads = stage.loads;
        const auto x_h =
            Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), pv.x_p );
        const auto status_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), pv.status_p );
        const std::vector<double> x( x_h.data(), x_h.data() + x_h.span() );
        const std::vector<int> status( status_h.data(),
                                       status_h.data() + status_h.span() );

        // Loads: a point selected by several loads carries their sum; each
        // distinct set of loads is one group with its own force.
        auto load_h = Kokkos::create_mirror( pv.load_p );
        Kokkos::deep_copy( load_h, -1 );
        const std::size_t num_points = x.size() / 2;
        std::vector<std::vector<int>> sets( num_points );
        load_counts.assign( loads.size(), 0 );
        for ( std::size_t l = 0; l < loads.size(); ++l )
        {
            const auto picked =
                selectPoints( loads[l].points, x, status, grid );
            for ( std::size_t p = 0; p < num_points; ++p )
                if ( picked[p] )
                {
                    sets[p].push_back( static_cast<int>( l ) );
                    ++load_counts[l];
                }
        }
        load_groups.clear();
        for ( std::size_t p = 0; p < num_points; ++p )
        {
            if ( sets[p].empty() )
                continue;
            auto it =
                std::find( load_groups.begin(), load_groups.end(), sets[p] );
            load_h( p ) = static_cast<int>( it - load_groups.begin() );
            if ( it == load_groups.end() )
                load_groups.push_back( sets[p] );
        }
        Kokkos::deep_copy( pv.load_p, load_h );
        load_force =
            LoadForceView<ExecSpace>( "load_force", load_groups.size() );
        empty_selections.clear();
        for ( std::size_t l = 0; l < loads.size(); ++l )
            if ( load_counts[l] == 0 )
                empty_selections.push_back( selectionKey( "loads", l ) );

        prescribed_p_w = Kokkos::View<double*, device_type>(
            "prescribed_p_w", pore_pressures.size() );
        prescribed_hold = Kokkos::View<int*, device_type>(
            "prescribed_hold", pore_pressures.size() );
        if ( wv.allocated() )
        {
            assignPorePressures( x, status, grid, wv );
            inflows = stage.inflows;
            inflow_flux_i = Kokkos::View<double***, device_type>(
                "inflow_flux_i", grid.cells[0] + 1, grid.cells[1] + 1, 2 );
            _particles = pv;
            _water_particles = wv;
            _grid = grid;
            assignInflows( x, status );
            next_surface_update_s = _follow_interval_s;
            for ( std::size_t f = 0; f < inflows.size(); ++f )
                if ( _inflow_counts[f] == 0 )
                    empty_selections.push_back( selectionKey( "inflows", f ) );
        }
        update( 0.0, 0.0 );
    }

    /*!
      \brief Which points each water inflow feeds, their volumes and
      weights, from the positions x and status; an inflow that follows the
      surface gets the horizontal projection of the fed cells as its
      length, one on a polyline the polyline's length and, on the points
      of each cell it feeds, the weight that gives the cell its share of
      the line (polylineCellShares). With following_only, only the
      inflows that follow the surface are selected again; the others keep
      the points chosen at the stage start.
    */
    void assignInflows( const std::vector<double>& x,
                        const std::vector<int>& status,
                        const bool following_only = false )
    {
        auto follows = [&]( const int f )
        { return inflows[f].follow_surface_interval_s > 0.0; };
        // Shared by the initial volumes (PorePressurePointUpdate divides by
        // the current one): the water added is exactly the prescribed.
        const auto vol_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), _particles.vol0_p );
        auto inflow_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), _water_particles.inflow_p );
        auto weight_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), _water_particles.inflow_weight_p );
        if ( following_only )
        {
            for ( std::size_t p = 0; p < inflow_h.extent( 0 ); ++p )
                if ( inflow_h( p ) >= 0 && follows( inflow_h( p ) ) )
                    inflow_h( p ) = -1;
        }
        else
        {
            Kokkos::deep_copy( inflow_h, -1 );
            Kokkos::deep_copy( weight_h, 1.0 );
            inflow_volumes.assign( inflows.size(), 0.0 );
            _inflow_counts.assign( inflows.size(), 0 );
            inflow_rate = Kokkos::View<double*, device_type>( "inflow_rate",
                                                              inflows.size() );
            inflow_ponding = Kokkos::View<int*, device_type>( "inflow_ponding",
                                                              inflows.size() );
            auto ponding_h = Kokkos::create_mirror_view( inflow_ponding );
            _follow_interval_s = 1.0e300;
            for ( std::size_t f = 0; f < inflows.size(); ++f )
            {
                ponding_h( f ) = inflows[f].ponding ? 1 : 0;
                if ( follows( f ) )
                    _follow_interval_s =
                        std::min( _follow_interval_s,
                                  inflows[f].follow_surface_interval_s );
            }
            Kokkos::deep_copy( inflow_ponding, ponding_h );
        }
        for ( std::size_t f = 0; f < inflows.size(); ++f )
        {
            if ( following_only && !follows( f ) )
                continue;
            if ( inflows[f].points.kind == PointSelection::Kind::Polyline )
            {
                assignPolylineInflow( static_cast<int>( f ), x, status, vol_h,
                                      inflow_h, weight_h );
                continue;
            }
            const auto picked =
                selectPoints( inflows[f].points, x, status, _grid );
            inflow_volumes[f] = 0.0;
            _inflow_counts[f] = 0;
            for ( std::size_t p = 0; p < picked.size(); ++p )
                if ( picked[p] )
                {
                    inflow_h( p ) = static_cast<int>( f );
                    weight_h( p ) = 1.0;
                    inflow_volumes[f] += vol_h( p );
                    ++_inflow_counts[f];
                }
            if ( follows( f ) )
                inflows[f].length_m = horizontalExtent( picked, x, _grid );
        }
        Kokkos::deep_copy( _water_particles.inflow_p, inflow_h );
        Kokkos::deep_copy( _water_particles.inflow_weight_p, weight_h );
    }

    //! Re-detects the surface for the inflows that follow it (stage time t).
    void followSurface( const double t )
    {
        const auto x_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), _particles.x_p );
        const auto status_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), _particles.status_p );
        assignInflows(
            std::vector<double>( x_h.data(), x_h.data() + x_h.span() ),
            std::vector<int>( status_h.data(),
                              status_h.data() + status_h.span() ),
            true );
        next_surface_update_s = t + _follow_interval_s;
    }

    /*!
      \brief Values of every condition over the step from stage time t0 to
      t: the prescribed p_w and the loads at t, the inflows' rates at their
      mean over the step (meanOfTimeFunction), so a step takes in exactly
      the water of its time span however long it is.
    */
    void update( const double t0, const double t )
    {
        if ( t >= next_surface_update_s )
            followSurface( t );
        auto p_h = Kokkos::create_mirror_view( prescribed_p_w );
        for ( std::size_t c = 0; c < pore_pressures.size(); ++c )
            p_h( c ) =
                pore_pressures[c].pressure_pa *
                evaluateTimeFunction( pore_pressures[c].time_function, t );
        Kokkos::deep_copy( prescribed_p_w, p_h );
        auto f_h = Kokkos::create_mirror_view( load_force );
        for ( std::size_t g = 0; g < load_groups.size(); ++g )
        {
            f_h( g, 0 ) = f_h( g, 1 ) = 0.0;
            for ( const int l : load_groups[g] )
            {
                // traction x length shared equally by the load's points.
                const double scale =
                    loads[l].length_m *
                    evaluateTimeFunction( loads[l].time_function, t ) /
                    load_counts[l];
                f_h( g, 0 ) += loads[l].traction_pa[0] * scale;
                f_h( g, 1 ) += loads[l].traction_pa[1] * scale;
            }
        }
        Kokkos::deep_copy( load_force, f_h );
        auto rate_h = Kokkos::create_mirror_view( inflow_rate );
        for ( std::size_t f = 0; f < inflows.size(); ++f )
            rate_h( f ) = inflow_volumes[f] > 0.0 && !inflows[f].onGridEdge()
                              ? inflows[f].flux_m_per_s * inflows[f].length_m *
                                    meanOfTimeFunction(
                                        inflows[f].time_function, t0, t ) /
                                    inflow_volumes[f]
                              : 0.0;
        Kokkos::deep_copy( inflow_rate, rate_h );
        updateEdgeFluxes( t0, t );
    }

  private:
    //! Key path of condition k of a list of the stage ("loads[0].where").
    static std::string selectionKey( const char* list, const std::size_t k )
    {
        return std::string( list ) + "[" + std::to_string( k ) + "].where";
    }

    //! The points of the pore-pressure conditions (a point selected by
    //! several takes the last) and the p_w a hold keeps: each held point's
    //! current one.
    void assignPorePressures( const std::vector<double>& x,
                              const std::vector<int>& status,
                              const GridConfig& grid,
                              const WaterParticleViews<ExecSpace>& wv )
    {
        auto condition_h = Kokkos::create_mirror( wv.p_w_condition_p );
        Kokkos::deep_copy( condition_h, -1 );
        for ( std::size_t c = 0; c < pore_pressures.size(); ++c )
        {
            const auto picked =
                selectPoints( pore_pressures[c].points, x, status, grid );
            const auto count = std::count( picked.begin(), picked.end(), true );
            for ( std::size_t p = 0; p < picked.size(); ++p )
                if ( picked[p] )
                    condition_h( p ) = static_cast<int>( c );
            if ( count == 0 )
                empty_selections.push_back(
                    selectionKey( "pore_pressures", c ) );
        }
        Kokkos::deep_copy( wv.p_w_condition_p, condition_h );
        auto hold_h = Kokkos::create_mirror_view( prescribed_hold );
        for ( std::size_t c = 0; c < pore_pressures.size(); ++c )
            hold_h( c ) = pore_pressures[c].hold_initial ? 1 : 0;
        Kokkos::deep_copy( prescribed_hold, hold_h );
        const auto p_w_h = Kokkos::create_mirror_view_and_copy(
            Kokkos::HostSpace(), wv.p_w_p );
        auto held_h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                           wv.p_w_held_p );
        for ( std::size_t p = 0; p < condition_h.extent( 0 ); ++p )
            if ( condition_h( p ) >= 0 && hold_h( condition_h( p ) ) )
                held_h( p ) = p_w_h( p );
        Kokkos::deep_copy( wv.p_w_held_p, held_h );
    }

    /*!
      \brief The points of polyline inflow f: those of the cells that take
      a share of the line (polylineSelectionShares), each weighted so that
      its cell takes share x flux x length (weight = share x fed volume /
      cell volume); the length is the polyline's.
    */
    template <class HostVolumes, class HostIndices, class HostWeights>
    void assignPolylineInflow( const int f, const std::vector<double>& x,
                               const std::vector<int>& status,
                               const HostVolumes& vol_h, HostIndices& inflow_h,
                               HostWeights& weight_h )
    {
        WaterInflow& inflow = inflows[f];
        inflow.length_m = polylineLength( inflow.points.polyline_m,
                                          inflow.points.polyline_measure );
        const auto shares =
            polylineSelectionShares( inflow.points, x, status, _grid );
        std::map<int, double> cell_volume;
        std::vector<int> cell_of( status.size(), -1 );
        for ( std::size_t p = 0; p < status.size(); ++p )
        {
            if ( status[p] != point_active )
                continue;
            const int cell = cellIndexAt( x[2 * p], x[2 * p + 1], _grid );
            if ( !shares.count( cell ) )
                continue;
            cell_of[p] = cell;
            cell_volume[cell] += vol_h( p );
        }
        inflow_volumes[f] = 0.0;
        for ( const auto& cell : cell_volume )
            inflow_volumes[f] += cell.second;
        _inflow_counts[f] = 0;
        for ( std::size_t p = 0; p < status.size(); ++p )
            if ( cell_of[p] >= 0 )
            {
                inflow_h( p ) = f;
                weight_h( p ) = shares.at( cell_of[p] ) * inflow_volumes[f] /
                                cell_volume[cell_of[p]];
                ++_inflow_counts[f];
            }
    }

    //! inflow_flux_i over the step from stage time t0 to t: each edge
    //! inflow's mean flux along the inward normal of its edge's nodes.
    void updateEdgeFluxes( const double t0, const double t )
    {
        bool any = false;
        for ( const WaterInflow& inflow : inflows )
            any = any || inflow.onGridEdge();
        if ( !any )
            return;
        auto flux_h = Kokkos::create_mirror_view( inflow_flux_i );
        // A plain fill: a host deep_copy of a value would start the host
        // backend's threads on every step.
        std::fill( flux_h.data(), flux_h.data() + flux_h.span(), 0.0 );
        const int nx = _grid.cells[0], ny = _grid.cells[1];
        for ( const WaterInflow& inflow : inflows )
        {
            if ( !inflow.onGridEdge() )
                continue;
            const double q = inflow.flux_m_per_s *
                             meanOfTimeFunction( inflow.time_function, t0, t );
            using Kind = PointSelection::Kind;
            const Kind kind = inflow.points.kind;
            const bool vertical =
                kind == Kind::LeftCells || kind == Kind::RightCells;
            const int count = vertical ? ny + 1 : nx + 1;
            for ( int k = 0; k < count; ++k )
            {
                const int i = kind == Kind::LeftCells    ? 0
                              : kind == Kind::RightCells ? nx
                                                         : k;
                const int j = kind == Kind::BottomCells ? 0
                              : kind == Kind::TopCells  ? ny
                                                        : k;
                // Inward: down from the top, up from the bottom, ...
                const double sign =
                    ( kind == Kind::TopCells || kind == Kind::RightCells )
                        ? -1.0
                        : 1.0;
                flux_h( i, j, vertical ? 0 : 1 ) += sign * q;
            }
        }
        Kokkos::deep_copy( inflow_flux_i, flux_h );
    }

    // Handles of the points the inflows follow (shallow copies).
    ParticleViews<ExecSpace> _particles;
    WaterParticleViews<ExecSpace> _water_particles;
    GridConfig _grid;
    double _follow_interval_s = 1.0e300;
    std::vector<int> _inflow_counts; //!< points each inflow fed at its start
};

} // namespace mpm

#endif // MPM_STAGE_CONDITIONS_HPP
