#ifndef MPM_GRID_GEOMETRY_HPP
#define MPM_GRID_GEOMETRY_HPP

#include <Kokkos_Core.hpp>

#include <cmath>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Structured grid of square cells and the bilinear (4-node) shape
  functions N_I(x) = (1 - |xi_I|)(1 - |eta_I|) of standard MPM.
*/
struct GridGeometry
{
    double x0 = 0.0; //!< origin x, m
    double y0 = 0.0; //!< origin y, m
    double h = 1.0;  //!< cell size, m
    int nx = 1;      //!< cells along x
    int ny = 1;      //!< cells along y

    //! Cell containing x; false if x lies outside the grid.
    KOKKOS_INLINE_FUNCTION bool cellOf( const double x, const double y, int& ci,
                                        int& cj ) const
    {
        // The same expressions as weights(), so both agree on the cell.
        const double inv_h = 1.0 / h;
        const double gx = ( x - x0 ) * inv_h;
        const double gy = ( y - y0 ) * inv_h;
        if ( !( gx >= 0.0 && gy >= 0.0 && gx < nx && gy < ny ) )
            return false;
        ci = static_cast<int>( gx );
        cj = static_cast<int>( gy );
        return true;
    }

    /*!
      \brief Bilinear weights and gradients of the 4 nodes of the cell that
      contains (x, y). Node k = a + 2 b is node (ci + a, cj + b).
      The caller guarantees the point lies in the grid.
    */
    KOKKOS_FORCEINLINE_FUNCTION void weights( const double x, const double y,
                                              int& ci, int& cj, double w[4],
                                              double dwdx[4],
                                              double dwdy[4] ) const
    {
        const double inv_h = 1.0 / h; // one division instead of four
        const double gx = ( x - x0 ) * inv_h;
        const double gy = ( y - y0 ) * inv_h;
        ci = static_cast<int>( gx );
        cj = static_cast<int>( gy );
        // Clamp points on the far edges into the last cell.
        ci = ci < nx ? ci : nx - 1;
        cj = cj < ny ? cj : ny - 1;
        const double xi = gx - ci;
        const double eta = gy - cj;
        const double wx[2] = { 1.0 - xi, xi };
        const double wy[2] = { 1.0 - eta, eta };
        const double gxw[2] = { -inv_h, inv_h };
        for ( int b = 0; b < 2; ++b )
            for ( int a = 0; a < 2; ++a )
            {
                const int k = a + 2 * b;
                w[k] = wx[a] * wy[b];
                dwdx[k] = gxw[a] * wy[b];
                dwdy[k] = wx[a] * gxw[b];
            }
    }

    //! Node coordinates.
    KOKKOS_INLINE_FUNCTION double nodeX( const int i ) const
    {
        return x0 + i * h;
    }
    KOKKOS_INLINE_FUNCTION double nodeY( const int j ) const
    {
        return y0 + j * h;
    }
    int numNodes() const { return ( nx + 1 ) * ( ny + 1 ); }
};

} // namespace physics
} // namespace mpm

#endif // MPM_GRID_GEOMETRY_HPP
