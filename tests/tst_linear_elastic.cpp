#include <physics/mpm_linear_elastic.hpp>
#include <physics/mpm_material_params.hpp>

#include <gtest/gtest.h>

namespace
{
// E = 10 MPa, nu = 0.25: lambda = G = 4 MPa, E_c = lambda + 2 G = 12 MPa.
mpm::physics::MaterialParams testParams()
{
    return mpm::physics::elasticParams( 10.0e6, 0.25, 2000.0 );
}

TEST( LinearElastic, uniaxial_strain_gives_constrained_modulus )
{
    const auto m = testParams();
    const double lambda = 4.0e6;
    const double e_c = 12.0e6;
    ASSERT_NEAR( m.constrainedModulus(), e_c, 1e-9 * e_c );

    // Start from a non-zero stress: the law is incremental.
    double s[4] = { -1.0e3, -2.0e3, 5.0e2, -3.0e3 };
    const double de[4] = { 0.0, -1.0e-3, 0.0, 0.0 };
    mpm::physics::LinearElastic{}( m, de, s );
    EXPECT_NEAR( s[0], -1.0e3 + lambda * de[1], 1e-9 * e_c * 1e-3 );
    EXPECT_NEAR( s[1], -2.0e3 + e_c * de[1], 1e-9 * e_c * 1e-3 );
    EXPECT_NEAR( s[2], 5.0e2, 1e-9 * e_c * 1e-3 );
    EXPECT_NEAR( s[3], -3.0e3 + lambda * de[1], 1e-9 * e_c * 1e-3 );
    // Hand values: -1000 - 4000, -2000 - 12000.
    EXPECT_NEAR( s[0], -5.0e3, 1e-6 );
    EXPECT_NEAR( s[1], -14.0e3, 1e-6 );
}

TEST( LinearElastic, pure_shear_uses_tensor_shear_strain )
{
    const auto m = testParams();
    const double two_g = 8.0e6;
    double s[4] = { 0.0, 0.0, 0.0, 0.0 };
    // Tensor shear 1e-3 (engineering shear 2e-3): s_xy = 2 G de_xy = 8 kPa.
    const double de[4] = { 0.0, 0.0, 1.0e-3, 0.0 };
    mpm::physics::LinearElastic{}( m, de, s );
    EXPECT_NEAR( s[2], two_g * 1.0e-3, 1e-6 );
    EXPECT_NEAR( s[2], 8.0e3, 1e-6 );
    EXPECT_EQ( s[0], 0.0 );
    EXPECT_EQ( s[1], 0.0 );
    EXPECT_EQ( s[3], 0.0 );
}

TEST( LinearElastic, volumetric_strain_gives_bulk_modulus )
{
    const auto m = testParams();
    double s[4] = { 0.0, 0.0, 0.0, 0.0 };
    const double de[4] = { 1.0e-4, 1.0e-4, 0.0, 1.0e-4 };
    mpm::physics::LinearElastic{}( m, de, s );
    // K = lambda + 2/3 G = 20/3 MPa; s = 3 K eps = 2 kPa on each axis.
    for ( int i : { 0, 1, 3 } )
        EXPECT_NEAR( s[i], 2.0e3, 1e-6 );
    EXPECT_EQ( s[2], 0.0 );
}

// Moduli that fall with dilation: a point stretched to J = V / V0 = 2.5
// takes the stress increments of K / J and G / J, 0.4 times those above;
// at J <= 1, or with constant moduli, those of K and G.
TEST( LinearElastic, moduli_are_per_unit_initial_volume )
{
    const auto m = testParams();
    EXPECT_DOUBLE_EQ( m.modulusFactor( 0.25, 0.1 ), 0.4 );
    EXPECT_DOUBLE_EQ( m.modulusFactor( 0.1, 0.1 ), 1.0 );
    EXPECT_DOUBLE_EQ( m.modulusFactor( 0.05, 0.1 ), 1.0 );
    const auto stretched = m.elasticAt( 0.25, 0.1 );
    EXPECT_NEAR( stretched.constrainedModulus(), 0.4 * 12.0e6, 1e-6 );
    EXPECT_EQ( stretched.density, m.density );

    double s[4] = { 0.0, 0.0, 0.0, 0.0 };
    const double de[4] = { 0.0, -1.0e-3, 1.0e-3, 0.0 };
    mpm::physics::LinearElastic{}( stretched, de, s );
    EXPECT_NEAR( s[1], -0.4 * 12.0e3, 1e-6 );
    EXPECT_NEAR( s[0], -0.4 * 4.0e3, 1e-6 );
    EXPECT_NEAR( s[2], 0.4 * 8.0e3, 1e-6 );

    auto constant = m;
    constant.moduli_fall_with_dilation = false;
    EXPECT_DOUBLE_EQ( constant.modulusFactor( 0.25, 0.1 ), 1.0 );
    EXPECT_NEAR( constant.elasticAt( 0.25, 0.1 ).constrainedModulus(), 12.0e6,
                 1e-6 );
}

} // namespace
