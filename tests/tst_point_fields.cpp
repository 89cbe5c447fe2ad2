// The point-field registry (src/records/mpm_point_fields.hpp) against the
// point structs: every output field names a View of ParticleViews or
// WaterParticleViews with its number of components, the water fields are
// marked two-phase, and no name repeats.
#include <mpm_particle_views.hpp>
#include <mpm_water_views.hpp>
#include <records/mpm_point_fields.hpp>

#include <Kokkos_Core.hpp>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace
{
//! The Views of one struct: components per point of each, by name.
template <class Views, class Visit>
std::map<std::string, int> viewComponents( const Views& views, Visit visit )
{
    std::map<std::string, int> components;
    visit( views,
           [&]( const char* name, const auto& view )
           {
               int c = 1;
               for ( unsigned r = 1; r < view.rank; ++r )
                   c *= static_cast<int>( view.extent( r ) );
               components[name] = c;
           } );
    return components;
}

TEST( PointFields, every_output_field_names_a_view )
{
    using Space = Kokkos::DefaultHostExecutionSpace;
    const auto solid = viewComponents( mpm::ParticleViews<Space>( 1 ),
                                       []( const auto& v, auto&& f )
                                       { mpm::forEachParticleView( v, f ); } );
    const auto water = viewComponents(
        mpm::WaterParticleViews<Space>( 1 ), []( const auto& v, auto&& f )
        { mpm::forEachWaterParticleView( v, f ); } );
    std::set<std::string> names;
    for ( const mpm::PointField& f : mpm::pointFields() )
    {
        SCOPED_TRACE( f.name );
        EXPECT_TRUE( names.insert( f.name ).second ) << "repeated name";
        if ( !f.view )
        {
            EXPECT_STREQ( f.name, "displacement" ) << "the only derived field";
            continue;
        }
        const auto& views = f.two_phase ? water : solid;
        const auto found = views.find( f.view );
        ASSERT_NE( found, views.end() )
            << f.view << " is no View of the "
            << ( f.two_phase ? "water" : "solid" ) << " point struct";
        EXPECT_EQ( found->second, f.components );
        EXPECT_EQ( mpm::snapshotMemberOf<double>( f.view ), f.values );
    }
    for ( const mpm::IntPointField& f : mpm::intPointFields() )
    {
        SCOPED_TRACE( f.name );
        EXPECT_TRUE( names.insert( f.name ).second ) << "repeated name";
        ASSERT_EQ( solid.count( f.view ), 1u );
        EXPECT_EQ( solid.at( f.view ), 1 );
        EXPECT_EQ( mpm::snapshotMemberOf<int>( f.view ), f.values );
    }
    EXPECT_EQ( mpm::snapshotMemberOf<double>( "du_p" ), nullptr );
}

} // namespace
