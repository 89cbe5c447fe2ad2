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
#include <sstream>
#include <string>

namespace
{
//! The Views of one struct: components per point of each, by name.
template <class Views>
std::map<std::string, int> viewComponents( const Views& views )
{
    std::map<std::string, int> components;
    mpm::forEachView( views,
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
    const auto solid = viewComponents( mpm::ParticleViews<Space>( 1 ) );
    const auto water = viewComponents( mpm::WaterParticleViews<Space>( 1 ) );
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

//---------------------------------------------------------------------------//
// A probed field names one probes.csv column per component, each column
// once; the fields in messages are named once too.
TEST( PointFields, probe_columns_match_components )
{
    std::set<std::string> columns, labels;
    for ( const mpm::PointField& f : mpm::pointFields() )
    {
        SCOPED_TRACE( f.name );
        EXPECT_TRUE( labels.insert( f.label ).second ) << "repeated label";
        if ( !f.probe_columns )
            continue;
        std::stringstream split( f.probe_columns );
        int count = 0;
        for ( std::string column; std::getline( split, column, ',' ); ++count )
        {
            EXPECT_FALSE( column.empty() );
            EXPECT_TRUE( columns.insert( column ).second ) << column;
        }
        EXPECT_EQ( count, f.components );
    }
    EXPECT_EQ( columns.size(), 11u ) << "x, u, v, eps_p_bar, p_w, S, v_w";
}

} // namespace
