#include <mpm_test_backends.hpp>
#include <mpm_test_cases.hpp>

#include <solver/drivers/mpm_run_stages.hpp>

#include <gtest/gtest.h>

namespace
{
MPM_TEST_BACKEND_SUITE( CompressionWave );

//! Records when a tracked point's velocity first falls below half of v0.
class ArrivalObserver : public mpm::RunObserver
{
  public:
    ArrivalObserver( const std::function<double()>& tracked_velocity,
                     const double v0 )
        : _tracked_velocity( tracked_velocity )
        , _v0( v0 )
    {
    }
    void onStep( const mpm::RunProgress& progress ) override
    {
        const double v = _tracked_velocity();
        if ( arrival_time < 0.0 && std::abs( v ) < 0.5 * std::abs( _v0 ) )
        {
            // Linear interpolation between the last two steps.
            const double f = ( _last_v - 0.5 * _v0 ) / ( _last_v - v );
            arrival_time = progress.time_s - progress.dt_s * ( 1.0 - f );
        }
        _last_v = v;
    }
    double arrival_time = -1.0;

  private:
    std::function<double()> _tracked_velocity;
    double _v0;
    double _last_v = 0.0;
};

//---------------------------------------------------------------------------//
// A column moving down at v0 hits a fixed base: the compression wave that
// stops it travels up at c = sqrt(E_c / rho). Its arrival time at height
// y is y / c (half-amplitude crossing).
TYPED_TEST( CompressionWave, arrival_time_matches_p_wave_speed )
{
    using exec_space = TypeParam;
    const double height = 10.0, h = 0.05, rho = 2000.0, E = 1.0e7, nu = 0.25;
    const double v0 = -0.01;
    mpm::StageConfig stage;
    stage.name = "impact";
    stage.type = mpm::StageType::Dynamic;
    stage.gravity_m_per_s2 = { 0.0, 0.0 };
    stage.duration_s = 0.1;
    auto config = mpm_test::columnCase(
        height, h, mpm_test::elasticMaterial( E, nu, rho ), stage );
    config.solver.courant_number = 0.5;
    config.solver.flip_fraction = 1.0;

    mpm::Simulation<exec_space> sim( config );
    Kokkos::deep_copy( sim.particles.v_p, 0.0 );
    auto v_sub = Kokkos::subview( sim.particles.v_p, Kokkos::ALL(), 1 );
    Kokkos::deep_copy( v_sub, v0 );

    // Track the point nearest y = 6 m.
    const auto x_h = Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(),
                                                          sim.particles.x_p );
    int tracked = 0;
    for ( int p = 0; p < sim.particles.size(); ++p )
        if ( std::abs( x_h( p, 1 ) - 6.0 ) <
             std::abs( x_h( tracked, 1 ) - 6.0 ) )
            tracked = p;
    const double y_tracked = x_h( tracked, 1 );
    auto v_p = sim.particles.v_p;
    ArrivalObserver observer(
        [=]()
        {
            auto v = Kokkos::subview( v_p, tracked, 1 );
            auto v_h =
                Kokkos::create_mirror_view_and_copy( Kokkos::HostSpace(), v );
            return v_h();
        },
        v0 );
    mpm::runStages( sim, config, observer );

    const double E_c = E * ( 1 - nu ) / ( ( 1 + nu ) * ( 1 - 2 * nu ) );
    const double c = std::sqrt( E_c / rho );
    const double expected = y_tracked / c;
    ASSERT_GT( observer.arrival_time, 0.0 ) << "the wave never arrived";
    EXPECT_NEAR( observer.arrival_time, expected, 0.02 * expected );
}

} // namespace
