#ifndef MPM_MOHR_COULOMB_HPP
#define MPM_MOHR_COULOMB_HPP

#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_principal_return.hpp>
#include <physics/mpm_tension_cutoff.hpp>

#include <Kokkos_Core.hpp>
#include <Kokkos_MathematicalFunctions.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Mohr-Coulomb yield function with the cohesion of Eqs. 14-15 of Wang,
  Vardon & Hicks (2018), Pa: f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi),
  principal stresses s1 >= s2 >= s3 (tension positive, s_zz included).
*/
KOKKOS_INLINE_FUNCTION double yieldFunction( const MaterialParams& m,
                                             const double s[4],
                                             const double eps_p_bar )
{
    const Impl::PrincipalExtremes p = Impl::principalExtremes( s );
    return Impl::yieldPrincipal( p.major, p.minor, cohesion( m, eps_p_bar ),
                                 m.sin_phi, m.cos_phi );
}

//---------------------------------------------------------------------------//
/*!
  \brief Non-associated Mohr-Coulomb with linear cohesion softening (Eqs.
  14-15 of Wang, Vardon & Hicks 2018); stress in Pa, strain in m/m.

  Elastic predictor (LinearElastic) and exact return mapping in principal
  stresses (de Souza Neto, Peric & Owen 2008, Sec. 8.2; Clausen, Damkilde &
  Andersen 2006): main plane, then the right or left edge, then the apex.
  Plastic potential g: f with phi replaced by the dilation angle psi.

  eps_p_bar is the accumulated plastic shear strain invariant,
    eps_p_bar = sum over steps of sqrt( 2/3 de_p : de_p ),
  de_p the deviatoric part of the plastic strain increment of the step.
  - Main plane: d(eps_p_bar) = 2/3 sqrt( 3 + sin^2 psi ) dgamma.
  - Edges: sqrt(2/3) |dev( dgamma_a b_a + dgamma_b b_b )|, solved with
    the cohesion by a scalar Newton iteration (Impl::faceReturn).
  - Apex: de_p = dev(sigma_tr) / 2G, so d(eps_p_bar) = q_tr / 3G (q_tr the
    von Mises stress of the trial), independent of c; then
    p = c(eps_p_bar_new) cot(phi).
  With softening on the engineering plastic shear strain instead
  (m.softening_measure), eps_p_bar accumulates (de_1 - de_3)^p: 2 dgamma on
  the main plane, (sigma_1 - sigma_3)_tr / 2G at the apex.
  - Tension cut-off (m.tension_cutoff, mpm_tension_cutoff.hpp): the same
    invariant of de_p = sum_k dgamma_k b_k over the active planes; a Rankine
    plane sigma_i = sigma_t (associated, b = e_i) gives 2/3 dgamma on its
    own, a hydrostatic return to sigma_1 = sigma_2 = sigma_3 = sigma_t none.
  Without a cut-off the results are those of the Mohr-Coulomb surface alone.
*/
struct MohrCoulomb
{
    //! Elastic predictor with de, then return mapping (updates s, eps_p_bar).
    KOKKOS_INLINE_FUNCTION ReturnRegion operator()( const MaterialParams& m,
                                                    const double de[4],
                                                    double s[4],
                                                    double& eps_p_bar ) const
    {
        LinearElastic{}( m, de, s );
        return returnMap( m, s, eps_p_bar );
    }

    //! Return mapping from the trial stress s (updated in place).
    KOKKOS_INLINE_FUNCTION ReturnRegion returnMap( const MaterialParams& m,
                                                   double s[4],
                                                   double& eps_p_bar ) const
    {
        // Yield checks on the trial's major and minor principal stresses
        // (NaN: not elastic); its principal axes only if it yields.
        const Impl::PrincipalExtremes trial = Impl::principalExtremes( s );
        const double c_n = cohesion( m, eps_p_bar );
        const bool shear =
            !( Impl::yieldPrincipal( trial.major, trial.minor, c_n, m.sin_phi,
                                     m.cos_phi ) <= 0.0 );
        const bool tension =
            m.tension_cutoff &&
            !( trial.major <= Impl::tensileStrength( m, c_n ) );
        if ( !shear && !tension )
            return ReturnRegion::Elastic;
        const Impl::PrincipalStress p = Impl::principalStress( s );
        const double* sigma_tr = p.sigma;

        // Every path below sets sigma (a trial that is not elastic yields
        // in shear or crosses the cut-off); the trial's values keep the
        // compiler from warning that it may not.
        double sigma[3] = { sigma_tr[0], sigma_tr[1], sigma_tr[2] };
        double eps_p_bar_new = eps_p_bar;
        ReturnRegion region = ReturnRegion::Elastic;
        if ( shear )
            region = mohrCoulombReturn( m, sigma_tr, c_n, eps_p_bar, sigma,
                                        eps_p_bar_new );
        // With a cut-off, a Mohr-Coulomb return above sigma_t is replaced.
        if ( m.tension_cutoff && !Impl::belowCutoff( m, region, sigma_tr, c_n,
                                                     sigma, eps_p_bar_new ) )
            region = Impl::tensionCutoffReturn( m, sigma_tr, eps_p_bar, sigma,
                                                eps_p_bar_new );

        // Rotate back with the trial in-plane principal directions.
        Impl::fromPrincipal( p, sigma, s );
        eps_p_bar = eps_p_bar_new;
        return region;
    }

    //! Mohr-Coulomb return of a yielding trial in principal stresses: main
    //! plane, then the right or left edge, then the apex.
    KOKKOS_INLINE_FUNCTION ReturnRegion mohrCoulombReturn(
        const MaterialParams& m, const double sigma_tr[3], const double c_n,
        const double eps_p_bar, double sigma[3], double& eps_p_bar_new ) const
    {
        namespace KE = Kokkos::Experimental;
        const double sin_phi = m.sin_phi;
        const double cos_phi = m.cos_phi;
        const double sin_psi = m.sin_psi;
        const double tol =
            1e-12 * ( KE::fabs( sigma_tr[0] ) + KE::fabs( sigma_tr[2] ) + c_n );

        // Main plane f_13.
        ReturnRegion region = ReturnRegion::MainPlane;
        const int main_face[2][2] = { { 0, 2 }, { 0, 2 } };
        Impl::faceReturn( m, 1, main_face, sigma_tr, eps_p_bar, sigma,
                          eps_p_bar_new );
        if ( sigma[0] < sigma[1] - tol || sigma[1] < sigma[2] - tol )
        {
            // Edge: right if sigma_2 = sigma_3 is reached first along D b.
            const bool right =
                ( 1.0 - sin_psi ) * ( sigma_tr[0] - sigma_tr[1] ) -
                    ( 1.0 + sin_psi ) * ( sigma_tr[1] - sigma_tr[2] ) >
                0.0;
            const int right_faces[2][2] = { { 0, 2 }, { 0, 1 } };
            const int left_faces[2][2] = { { 0, 2 }, { 1, 2 } };
            Impl::faceReturn( m, 2, right ? right_faces : left_faces, sigma_tr,
                              eps_p_bar, sigma, eps_p_bar_new );
            region = right ? ReturnRegion::RightEdge : ReturnRegion::LeftEdge;
            // Past the apex (p > c cot(phi)) the edge ordering is inverted.
            const bool past_apex =
                right ? sigma[0] < sigma[1] - tol : sigma[1] < sigma[2] - tol;
            if ( past_apex && sin_phi > 1e-12 )
            {
                // Apex: the trial deviator is all plastic; then
                // p = c(eps_p_bar) cot(phi).
                eps_p_bar_new = eps_p_bar + Impl::apexIncrement( m, sigma_tr );
                const double p_apex =
                    cohesion( m, eps_p_bar_new ) * cos_phi / sin_phi;
                sigma[0] = sigma[1] = sigma[2] = p_apex;
                region = ReturnRegion::Apex;
            }
        }
        return region;
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_MOHR_COULOMB_HPP
