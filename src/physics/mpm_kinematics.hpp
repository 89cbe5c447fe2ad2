#ifndef MPM_KINEMATICS_HPP
#define MPM_KINEMATICS_HPP

#include <Kokkos_Core.hpp>

#include <cmath>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Strain increment and objective stress rotation of one point from
  its velocity gradient L_ij = dv_i/dx_j over a step dt:
  de = sym(L) dt (tensor shear, de_zz = 0 in plane strain), and the
  Jaumann rotation s <- s + dt (W s - s W), W = skew(L).
*/
struct Kinematics
{
    double dt; //!< time step, s

    //! de = {xx, yy, xy, zz}, tensor shear component.
    KOKKOS_INLINE_FUNCTION void strainIncrement( const double L[2][2],
                                                 double de[4] ) const
    {
        de[0] = L[0][0] * dt;
        de[1] = L[1][1] * dt;
        de[2] = 0.5 * ( L[0][1] + L[1][0] ) * dt;
        de[3] = 0.0;
    }

    //! Jaumann rotation of s = {xx, yy, xy, zz}; W_xy = (L_xy - L_yx) / 2.
    KOKKOS_INLINE_FUNCTION void rotate( const double L[2][2],
                                        double s[4] ) const
    {
        const double w_dt = 0.5 * ( L[0][1] - L[1][0] ) * dt;
        const double s_xx = s[0];
        const double s_yy = s[1];
        const double s_xy = s[2];
        s[0] = s_xx + 2.0 * w_dt * s_xy;
        s[1] = s_yy - 2.0 * w_dt * s_xy;
        s[2] = s_xy + w_dt * ( s_yy - s_xx );
    }

    //! Volume ratio of the step, det(I + L dt).
    KOKKOS_INLINE_FUNCTION double volumeRatio( const double L[2][2] ) const
    {
        return ( 1.0 + L[0][0] * dt ) * ( 1.0 + L[1][1] * dt ) -
               L[0][1] * L[1][0] * dt * dt;
    }
};

/*!
  \brief FLIP fraction of a step of size dt: `flip_fraction` at a step of
  the reference `dt_reference` (the explicit scheme's CFL limit), and
  proportionally less PIC at smaller steps, 1 - (1 - flip) dt / reference;
  at longer steps (the semi-implicit scheme's) flip^(dt / reference), as
  that many reference steps would blend. The PIC part damps every step (the
  water's flow relative to the solid too), so a fixed blend would damp
  more per second the smaller the step: a wetting column took up 25 %
  less water at a twentieth of the step. Scaled, the damping per second
  depends on neither the step nor the scheme.
*/
inline double stepFlipFraction( const double flip_fraction, const double dt,
                                const double dt_reference )
{
    if ( !( dt_reference > 0.0 ) )
        return flip_fraction;
    const double ratio = dt / dt_reference;
    return ratio <= 1.0 ? 1.0 - ( 1.0 - flip_fraction ) * ratio
                        : std::pow( flip_fraction, ratio );
}

} // namespace physics
} // namespace mpm

#endif // MPM_KINEMATICS_HPP
