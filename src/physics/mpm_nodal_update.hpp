#ifndef MPM_NODAL_UPDATE_HPP
#define MPM_NODAL_UPDATE_HPP

#include <mpm_device_type.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Explicit nodal velocity update of the single-phase momentum
  balance, m_i a_i = f_i - damping |f_i| sign(v_i) (local damping), with
  velocity boundary conditions. Units: kg, kg m/s, N, m/s.
*/
struct DryNodalUpdate
{
    double dt;      //!< time step, s
    double damping; //!< local damping coefficient, 0 <= damping < 1
    double inertia_scaling = 1.0; //!< factor on the inertial mass

    //! One direction of one node; `fixed` zeroes the new velocity.
    KOKKOS_INLINE_FUNCTION void operator()( const double m, const double p,
                                            const double f, const bool fixed,
                                            double& v_new, double& dv ) const
    {
        const double v_old = p / m;
        const double sign_v = ( v_old > 0.0 ) - ( v_old < 0.0 );
        const double f_damped =
            f - damping * Kokkos::Experimental::fabs( f ) * sign_v;
        v_new = fixed ? 0.0 : v_old + dt * f_damped / ( inertia_scaling * m );
        dv = v_new - v_old;
    }
};

//! Applies the node's boundary flags to a velocity.
KOKKOS_INLINE_FUNCTION void applyVelocityBC( const int flags, double& v_x,
                                             double& v_y )
{
    if ( flags & node_fix_x )
        v_x = 0.0;
    if ( flags & node_fix_y )
        v_y = 0.0;
}

} // namespace physics
} // namespace mpm

#endif // MPM_NODAL_UPDATE_HPP
