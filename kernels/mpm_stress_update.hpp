#ifndef MPM_STRESS_UPDATE_HPP
#define MPM_STRESS_UPDATE_HPP

#include <mpm_particle_views.hpp>
#include <physics/mpm_kinematics.hpp>
#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_mohr_coulomb.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Stress update of one point from its velocity gradient L: Jaumann
  rotation, then its constitutive model on the strain increment sym(L) dt
  with the moduli at the point's volume (MaterialParams::elasticAt);
  accumulates strain and updates the volume by det(I + L dt).
*/
template <class ExecSpace>
struct StressPointUpdate
{
    using pv_type = ParticleViews<ExecSpace>;
    physics::Kinematics kinematics;
    UnmanagedView<typename pv_type::tensor_view> sigma_p;
    UnmanagedView<typename pv_type::tensor_view> eps_p;
    UnmanagedView<typename pv_type::scalar_view> eps_p_bar_p;
    UnmanagedView<typename pv_type::scalar_view> vol_p;
    UnmanagedView<typename pv_type::scalar_view> vol0_p;

    StressPointUpdate( const ParticleViews<ExecSpace>& pv, const double dt )
        : kinematics{ dt }
        , sigma_p( pv.sigma_p )
        , eps_p( pv.eps_p )
        , eps_p_bar_p( pv.eps_p_bar_p )
        , vol_p( pv.vol_p )
        , vol0_p( pv.vol0_p )
    {
    }

    KOKKOS_INLINE_FUNCTION void
    operator()( const int p, const double L[2][2],
                const physics::MaterialParams& params ) const
    {
        double de[4];
        kinematics.strainIncrement( L, de );
        double s[4] = { sigma_p( p, 0 ), sigma_p( p, 1 ), sigma_p( p, 2 ),
                        sigma_p( p, 3 ) };
        kinematics.rotate( L, s );

        const physics::MaterialParams material =
            params.elasticAt( vol_p( p ), vol0_p( p ) );
        if ( material.model == physics::Model::MohrCoulomb )
            physics::MohrCoulomb{}( material, de, s, eps_p_bar_p( p ) );
        else
            physics::LinearElastic{}( material, de, s );

        for ( int c = 0; c < 4; ++c )
        {
            sigma_p( p, c ) = s[c];
            eps_p( p, c ) += de[c];
        }
        vol_p( p ) *= kinematics.volumeRatio( L );
    }
};

} // namespace mpm

#endif // MPM_STRESS_UPDATE_HPP
