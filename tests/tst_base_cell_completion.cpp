// physics::BaseCellCompletion: what the empty part of a cell cut by a fixed
// base adds to its corners, against direct integration over the cell.
#include <physics/mpm_base_cell.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
const double h = 0.5;
const double gauss[2] = { 0.5 - 0.5 / std::sqrt( 3.0 ),
                          0.5 + 0.5 / std::sqrt( 3.0 ) };

//! A point of the soil: local coordinates and volume.
struct Point
{
    double xi, eta, vol;
};

//! grad N_k at local (xi, eta), 1/m (corner k = a + 2 b).
void gradN( const int k, const double xi, const double eta, double g[2] )
{
    const int a = k & 1, b = k >> 1;
    g[0] = ( 2 * a - 1 ) * ( b ? eta : 1.0 - eta ) / h;
    g[1] = ( 2 * b - 1 ) * ( a ? xi : 1.0 - xi ) / h;
}

//! The completion's sums of the points and the corner's D and E.
struct Missing
{
    double D[2], E[2][2], centre[2];
};
Missing missingOf( const int k, const std::vector<Point>& points )
{
    double m0 = 0, m_xi = 0, m_eta = 0, m_xi_eta = 0, m_xi_xi = 0,
           m_eta_eta = 0;
    for ( const auto& p : points )
    {
        m0 += p.vol;
        m_xi += p.vol * p.xi;
        m_eta += p.vol * p.eta;
        m_xi_eta += p.vol * p.xi * p.eta;
        m_xi_xi += p.vol * p.xi * p.xi;
        m_eta_eta += p.vol * p.eta * p.eta;
    }
    const mpm::physics::BaseCellCompletion completion{ h };
    Missing m{};
    completion.missing( k, m0, m_xi, m_eta, m.D );
    completion.missingMoments( k, m0, m_xi, m_eta, m_xi_eta, m_xi_xi, m_eta_eta,
                               m.E );
    m.centre[0] = h * m_xi / m0;
    m.centre[1] = h * m_eta / m0;
    return m;
}

/*!
  int_(cell \ soil) f grad N_k for a field f(x, y) (x, y from the cell's
  corner, m): 3 x 3 Gauss over the cell (exact for these products of
  polynomials) less the points' sum.
*/
template <class Field>
void integrateMissing( const int k, const std::vector<Point>& points,
                       const Field& f, double out[2] )
{
    const double q[3] = { 0.5 - 0.5 * std::sqrt( 0.6 ), 0.5,
                          0.5 + 0.5 * std::sqrt( 0.6 ) };
    const double w[3] = { 5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0 };
    out[0] = out[1] = 0.0;
    double g[2];
    for ( int i = 0; i < 3; ++i )
        for ( int j = 0; j < 3; ++j )
        {
            gradN( k, q[i], q[j], g );
            const double value = f( h * q[i], h * q[j] );
            for ( int d = 0; d < 2; ++d )
                out[d] += w[i] * w[j] * h * h * value * g[d];
        }
    for ( const auto& p : points )
    {
        gradN( k, p.xi, p.eta, g );
        const double value = f( h * p.xi, h * p.eta );
        for ( int d = 0; d < 2; ++d )
            out[d] -= p.vol * value * g[d];
    }
}

//! The soils: all four Gauss points, the upper row (a base through the
//! cell's lower half), three unequal points.
std::vector<std::vector<Point>> soils()
{
    const double v = 0.25 * h * h;
    return { { { gauss[0], gauss[0], v },
               { gauss[1], gauss[0], v },
               { gauss[0], gauss[1], v },
               { gauss[1], gauss[1], v } },
             { { gauss[0], gauss[1], v }, { gauss[1], gauss[1], v } },
             { { 0.2, 0.7, 0.3 * v },
               { 0.9, 0.55, 0.5 * v },
               { 0.45, 0.95, 0.2 * v } } };
}

// A full cell of 2 x 2 Gauss points misses nothing; one row of points
// (the soil above a base through the cell) misses the lower half.
TEST( BaseCellCompletion, missing_area_integral )
{
    const auto all = soils();
    for ( int k = 0; k < 4; ++k )
    {
        const Missing full = missingOf( k, all[0] );
        for ( int i = 0; i < 2; ++i )
        {
            EXPECT_NEAR( full.D[i], 0.0, 1e-15 );
            for ( int j = 0; j < 2; ++j )
                EXPECT_NEAR( full.E[i][j], 0.0, 1e-15 );
        }
        // The upper row only (eta = g[1]): the top corners miss h/4 of the
        // full cell's int dN/dy = h/2; the bottom corners -h/4.
        const Missing row = missingOf( k, all[1] );
        EXPECT_NEAR( row.D[1], ( k >> 1 ) ? 0.25 * h : -0.25 * h, 1e-15 ) << k;
    }
}

// A linear pore pressure and total stress over the empty part: the forces
// from the soil's centre values and gradients equal the integrals, for
// every corner and soil (a mean alone would miss the gradient's share).
TEST( BaseCellCompletion, linear_fields_are_integrated_exactly )
{
    const double p_0 = 2.0e4, dp[2] = { 1.5e3, -9.81e3 };
    const double sigma_0[3] = { -3.0e4, -5.0e4, 4.0e3 };
    const double dsigma_dx[3] = { 2.0e3, -1.0e3, 7.0e2 };
    const double dsigma_dy[3] = { -1.1e4, -2.1e4, 3.0e3 };
    for ( const auto& soil : soils() )
        for ( int k = 0; k < 4; ++k )
        {
            const Missing m = missingOf( k, soil );
            const auto pressure = [&]( const double x, const double y ) {
                return p_0 + dp[0] * ( x - m.centre[0] ) +
                       dp[1] * ( y - m.centre[1] );
            };
            double expected[2], f[2];
            integrateMissing( k, soil, pressure, expected );
            mpm::physics::BaseCellCompletion::waterForce( m.D, m.E, p_0, dp,
                                                          f );
            for ( int d = 0; d < 2; ++d )
                EXPECT_NEAR( f[d], expected[d], 1e-10 * std::abs( p_0 ) * h );
            // -int sigma . grad N: row j = component (j, l) times dN/dx_l.
            double mixture[2] = { 0.0, 0.0 };
            const int component[2][2] = { { 0, 2 }, { 2, 1 } };
            for ( int j = 0; j < 2; ++j )
                for ( int l = 0; l < 2; ++l )
                {
                    const int c = component[j][l];
                    const auto sigma = [&]( const double x, const double y )
                    {
                        return sigma_0[c] + dsigma_dx[c] * ( x - m.centre[0] ) +
                               dsigma_dy[c] * ( y - m.centre[1] );
                    };
                    double integral[2];
                    integrateMissing( k, soil, sigma, integral );
                    mixture[j] -= integral[l];
                }
            mpm::physics::BaseCellCompletion::mixtureForce(
                m.D, m.E, sigma_0, dsigma_dx, dsigma_dy, f );
            for ( int d = 0; d < 2; ++d )
                EXPECT_NEAR( f[d], mixture[d], 1e-10 * 5.0e4 * h );
        }
}

// The empty part holds its weight: div sigma + rho g = 0, grad p_w = rho_w
// g, the stress across gravity growing as the cell's ratio (here 0.5),
// for gravity down and tilted by 20 degrees.
TEST( BaseCellCompletion, empty_part_holds_its_weight )
{
    const double rho = 2190.0, rho_w = 1000.0, pi = std::acos( -1.0 );
    for ( const double tilt : { 0.0, 20.0 * pi / 180.0 } )
    {
        const double g[2] = { 9.81 * std::sin( tilt ),
                              -9.81 * std::cos( tilt ) };
        // sigma = -(100 d d^T + 50 t t^T) kPa (d = g / |g|, t across it).
        const double d[2] = { g[0] / 9.81, g[1] / 9.81 };
        const double t[2] = { -d[1], d[0] };
        const double sigma[3] = { -1.0e5 * d[0] * d[0] - 5.0e4 * t[0] * t[0],
                                  -1.0e5 * d[1] * d[1] - 5.0e4 * t[1] * t[1],
                                  -1.0e5 * d[0] * d[1] - 5.0e4 * t[0] * t[1] };
        const auto grad = mpm::physics::BaseCellCompletion::weightGradients(
            g, rho, rho_w, sigma );
        // div sigma: (dxx/dx + dxy/dy, dxy/dx + dyy/dy).
        EXPECT_NEAR( grad.dsigma_dx[0] + grad.dsigma_dy[2] + rho * g[0], 0.0,
                     1e-9 );
        EXPECT_NEAR( grad.dsigma_dx[2] + grad.dsigma_dy[1] + rho * g[1], 0.0,
                     1e-9 );
        EXPECT_DOUBLE_EQ( grad.dp_w[0], rho_w * g[0] );
        EXPECT_DOUBLE_EQ( grad.dp_w[1], rho_w * g[1] );
        // Along t the normal stress grows with depth at half the rate.
        const auto along = [&]( const double u[2], const double* dsigma )
        {
            return dsigma[0] * u[0] * u[0] + dsigma[1] * u[1] * u[1] +
                   2.0 * dsigma[2] * u[0] * u[1];
        };
        double across_rate = 0.0, down_rate = 0.0;
        for ( int k = 0; k < 2; ++k )
        {
            const double* dsigma = k == 0 ? grad.dsigma_dx : grad.dsigma_dy;
            across_rate += d[k] * along( t, dsigma );
            down_rate += d[k] * along( d, dsigma );
        }
        EXPECT_NEAR( down_rate, -rho * 9.81, 1e-9 );
        EXPECT_NEAR( across_rate, -0.5 * rho * 9.81, 1e-9 );
    }
}

} // namespace
