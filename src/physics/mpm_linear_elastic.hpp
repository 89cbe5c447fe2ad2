#ifndef MPM_LINEAR_ELASTIC_HPP
#define MPM_LINEAR_ELASTIC_HPP

#include <physics/mpm_material_params.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
namespace physics
{
//---------------------------------------------------------------------------//
/*!
  \brief Isotropic Hooke's law, stress increment s += D : de (Pa).

  Stress layout s[4] = {xx, yy, xy, zz}, tension positive, Pa.
  Strain increment layout de[4] = {xx, yy, xy, zz}; de[2] is the tensor shear
  component (half the engineering shear); de[3] = 0 in plane strain.

  With lambda = K - 2/3 G and tr(de) = de_xx + de_yy + de_zz:
    ds_ii = lambda tr(de) + 2 G de_ii  (ii = xx, yy, zz),   ds_xy = 2 G de_xy.
*/
struct LinearElastic
{
    KOKKOS_INLINE_FUNCTION void
    operator()( const MaterialParams& m, const double de[4], double s[4] ) const
    {
        const double two_g = 2.0 * m.shear_modulus;
        const double lambda = m.bulk_modulus - two_g / 3.0;
        const double lambda_tr = lambda * ( de[0] + de[1] + de[3] );
        s[0] += lambda_tr + two_g * de[0];
        s[1] += lambda_tr + two_g * de[1];
        s[2] += two_g * de[2];
        s[3] += lambda_tr + two_g * de[3];
    }
};

} // namespace physics
} // namespace mpm

#endif // MPM_LINEAR_ELASTIC_HPP
