#include <physics/mpm_water_storage.hpp>

#include <gtest/gtest.h>

namespace
{
// Eq. 8's storage: the retention slope and the water's compression.
TEST( WaterStorage, storage_is_retention_slope_plus_compression )
{
    EXPECT_DOUBLE_EQ( mpm::physics::waterStorage( 0.3, 0.5, 2.0e-5, 2.0e9 ),
                      0.3 * 2.0e-5 + 0.3 * 0.5 / 2.0e9 );
}

} // namespace
