#ifndef MPM_MATERIAL_PARAMS_HPP
#define MPM_MATERIAL_PARAMS_HPP

#include <physics/mpm_retention_params.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <limits>

namespace mpm
{
namespace physics
{
//! Constitutive model selector stored per material.
enum class Model : int
{
    LinearElastic = 0,
    MohrCoulomb = 1
};

//! The plastic strain measure the cohesion softens on (Eq. 14), stored in
//! eps_p_bar: the paper's equivalent plastic shear strain sum sqrt( 2/3
//! de_p : de_p ) (deviatoric de_p), or the engineering plastic shear strain
//! sum ( de_1 - de_3 )^p (largest minus smallest principal increment).
enum class SofteningMeasure : int
{
    EquivalentPlasticStrain = 0,
    EngineeringShearStrain = 1
};

//---------------------------------------------------------------------------//
/*!
  \brief Parameters of one material, in SI units and radians.

  Plain data, copied by value into kernels. Stress is tension positive.
*/
struct MaterialParams
{
    Model model = Model::LinearElastic;
    double density = 0.0;           //!< bulk density, kg/m^3
    double bulk_modulus = 0.0;      //!< K = E / (3 (1 - 2 nu)), Pa
    double shear_modulus = 0.0;     //!< G = E / (2 (1 + nu)), Pa
    double cohesion_peak = 0.0;     //!< c0, Pa
    double cohesion_residual = 0.0; //!< c_r, Pa
    double softening_modulus = 0.0; //!< H = dc / d(eps_p_bar), Pa (<= 0)
    double friction_angle = 0.0;    //!< phi, rad (set with setAngles)
    double dilation_angle = 0.0;    //!< psi, rad (set with setAngles)
    double sin_phi = 0.0;           //!< sin(phi), cached for the kernels
    double cos_phi = 1.0;           //!< cos(phi)
    double sin_psi = 0.0;           //!< sin(psi)
    //! Tension cut-off: peak tensile strength sigma_t0, Pa (+infinity: none),
    //! softened with the cohesion, sigma_t = sigma_t0 c / c0 (set with
    //! setTensileStrength after the cohesion and the angles).
    double tensile_strength = std::numeric_limits<double>::infinity();
    double tensile_ratio = 0.0;  //!< sigma_t0 / c0, so sigma_t = ratio * c
    bool tension_cutoff = false; //!< sigma_t0 < c0 cot(phi): cut-off active
    //! What eps_p_bar (and so the cohesion's softening) measures.
    SofteningMeasure softening_measure =
        SofteningMeasure::EquivalentPlasticStrain;
    //! A point dilated to J = V / V0 > 1 has the moduli K / J and G / J
    //! (elasticAt), so its stiffness per unit mass, its P-wave speed and the
    //! stable step do not grow as it stretches; at J <= 1, K and G
    //! (solver.moduli_fall_with_dilation).
    bool moduli_fall_with_dilation = true;
    // Two-phase scenes only.
    double permeability = 0.0; //!< intrinsic permeability k, m^2
    RetentionParams retention; //!< S(p_w), k_rel(S)

    //! Friction and dilation angles (rad) with their cached sines/cosines.
    void setAngles( const double phi, const double psi )
    {
        friction_angle = phi;
        dilation_angle = psi;
        sin_phi = std::sin( phi );
        cos_phi = std::cos( phi );
        sin_psi = std::sin( psi );
    }

    //! Tension cut-off sigma_t0 (Pa, +infinity: none). One at or above the
    //! apex c0 cot(phi) never acts, nor one within 1e-9 of it (a sliver):
    //! then the Mohr-Coulomb surface holds alone, as without a cut-off.
    void setTensileStrength( const double sigma_t0 )
    {
        tensile_strength = sigma_t0;
        const double apex = sin_phi > 0.0
                                ? cohesion_peak * cos_phi / sin_phi
                                : std::numeric_limits<double>::infinity();
        tension_cutoff = std::isfinite( sigma_t0 ) && sigma_t0 >= 0.0 &&
                         cohesion_peak > 0.0 &&
                         sigma_t0 < apex * ( 1.0 - 1e-9 );
        tensile_ratio = tension_cutoff ? sigma_t0 / cohesion_peak : 0.0;
    }

    //! Constrained (P-wave) modulus E_c = K + 4/3 G, Pa.
    KOKKOS_INLINE_FUNCTION double constrainedModulus() const
    {
        return bulk_modulus + 4.0 / 3.0 * shear_modulus;
    }

    //! The factor on K and G of a point of volume vol and initial volume
    //! vol0: V0 / V if it has dilated (V > V0) and moduli_fall_with_dilation,
    //! else 1.
    KOKKOS_INLINE_FUNCTION double modulusFactor( const double vol,
                                                 const double vol0 ) const
    {
        return moduli_fall_with_dilation && vol > vol0 ? vol0 / vol : 1.0;
    }

    //! The material of a point of volume vol and initial volume vol0: K and
    //! G times modulusFactor (docs/formulation.md, step 8).
    KOKKOS_INLINE_FUNCTION MaterialParams elasticAt( const double vol,
                                                     const double vol0 ) const
    {
        MaterialParams at = *this;
        const double factor = modulusFactor( vol, vol0 );
        at.bulk_modulus *= factor;
        at.shear_modulus *= factor;
        return at;
    }
};

//! Parameters from Young's modulus and Poisson's ratio.
inline MaterialParams elasticParams( const double youngs_modulus,
                                     const double poisson_ratio,
                                     const double density )
{
    MaterialParams params;
    params.density = density;
    params.bulk_modulus =
        youngs_modulus / ( 3.0 * ( 1.0 - 2.0 * poisson_ratio ) );
    params.shear_modulus = youngs_modulus / ( 2.0 * ( 1.0 + poisson_ratio ) );
    return params;
}

//! Pore-water constants (two-phase scenes), SI.
struct WaterParams
{
    double density = 1000.0;     //!< rho_w, kg/m^3
    double bulk_modulus = 2.2e9; //!< K_w, Pa
    double viscosity = 1.0e-3;   //!< mu_w, Pa s
};

//! Fixed-capacity table of materials, indexed by a point's material id.
struct MaterialTable
{
    static constexpr int capacity = 16;
    MaterialParams materials[capacity];
    int size = 0;

    KOKKOS_INLINE_FUNCTION const MaterialParams&
    operator[]( const int id ) const
    {
        return materials[id];
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_MATERIAL_PARAMS_HPP
