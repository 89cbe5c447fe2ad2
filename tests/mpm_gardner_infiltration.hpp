#ifndef MPM_GARDNER_INFILTRATION_HPP
#define MPM_GARDNER_INFILTRATION_HPP

#include <cmath>
#include <vector>

namespace mpm_test
{
/*!
  \brief Exact transient infiltration into a rigid column of Gardner soil
  (Srivastava & Yeh 1991, homogeneous case): K = K_s exp(alpha psi),
  theta - theta_r = (theta_s - theta_r) K / K_s, a water table (psi = 0) at
  z = 0, a surface flux q at z = L. Richards' equation in k = K / K_s,
  Z = alpha z, T = alpha K_s t / (theta_s - theta_r) is linear:
    dk/dT = d2k/dZ2 + dk/dZ,  k(0) = 1,  dk/dZ + k = q_B at Z = alpha L.
  From the steady profile of a flux q_A, k_A = q_A + (1 - q_A) exp(-Z), the
  flux changes to q_B at t = 0:
    k = q_B + (1 - q_B) exp(-Z)
        + exp(-Z/2 - T/4) sum_n c_n sin(lambda_n Z) exp(-lambda_n^2 T),
  lambda_n the roots of tan(lambda alpha L) + 2 lambda = 0, c_n the sine
  coefficients of exp(Z/2) (k_A - k_B). (Derived here: u = k - k_B =
  exp(-Z/2 - T/4) w turns the equation into w_T = w_ZZ with w(0) = 0 and
  w_Z + w/2 = 0 at alpha L.)
*/
class GardnerInfiltration
{
  public:
    //! alpha (1/m of head), L (m), fluxes q_A, q_B (units of K_s, >0 down).
    GardnerInfiltration( const double alpha, const double length,
                         const double q_A, const double q_B,
                         const int terms = 200 )
        : _alpha( alpha )
        , _L( alpha * length )
        , _q_B( q_B )
    {
        const double pi = std::acos( -1.0 );
        for ( int n = 1; n <= terms; ++n )
        {
            // g = sin(l L) + 2 l cos(l L) changes sign on
            // ((n - 1/2) pi / L, n pi / L).
            double lo = ( n - 0.5 ) * pi / _L, hi = n * pi / _L;
            const auto g = [&]( const double l )
            { return std::sin( l * _L ) + 2.0 * l * std::cos( l * _L ); };
            const double g_lo = g( lo );
            for ( int k = 0; k < 200; ++k )
            {
                const double mid = 0.5 * ( lo + hi );
                ( g( mid ) * g_lo > 0.0 ? lo : hi ) = mid;
            }
            const double l = 0.5 * ( lo + hi );
            // int_0^L e^{a z} sin(l z) dz for a = +-1/2.
            const auto moment = [&]( const double a )
            {
                return ( std::exp( a * _L ) * ( a * std::sin( l * _L ) -
                                                l * std::cos( l * _L ) ) +
                         l ) /
                       ( a * a + l * l );
            };
            const double norm =
                0.5 * _L - std::sin( 2.0 * l * _L ) / ( 4.0 * l );
            _lambda.push_back( l );
            _c.push_back( ( q_A - q_B ) * ( moment( 0.5 ) - moment( -0.5 ) ) /
                          norm );
        }
    }

    //! K / K_s at height z (m) above the water table and dimensionless
    //! time T (tStar()).
    double relativeConductivity( const double z, const double t_star ) const
    {
        const double zs = _alpha * z;
        double sum = 0.0;
        for ( std::size_t n = 0; n < _lambda.size(); ++n )
            sum += _c[n] * std::sin( _lambda[n] * zs ) *
                   std::exp( -_lambda[n] * _lambda[n] * t_star );
        return _q_B + ( 1.0 - _q_B ) * std::exp( -zs ) +
               std::exp( -0.5 * zs - 0.25 * t_star ) * sum;
    }

    //! T of time t (s): alpha K_s t / (theta_s - theta_r).
    double tStar( const double t, const double K_s,
                  const double theta_range ) const
    {
        return _alpha * K_s * t / theta_range;
    }

  private:
    double _alpha, _L, _q_B;
    std::vector<double> _lambda, _c;
};

} // namespace mpm_test

#endif // MPM_GARDNER_INFILTRATION_HPP
