#ifndef MPM_MATERIAL_PARAMS_HPP
#define MPM_MATERIAL_PARAMS_HPP

#include <Kokkos_Core.hpp>

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
    double friction_angle = 0.0;    //!< phi, rad
    double dilation_angle = 0.0;    //!< psi, rad

    //! Constrained (P-wave) modulus E_c = K + 4/3 G, Pa.
    KOKKOS_INLINE_FUNCTION double constrainedModulus() const
    {
        return bulk_modulus + 4.0 / 3.0 * shear_modulus;
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
