#include <io/mpm_checkpoint_loop.hpp>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <type_traits>

namespace mpm
{
namespace Impl
{
namespace
{
const char* const who = "mpm::Checkpoint";

std::string groupName( const std::size_t index )
{
    char buffer[32];
    std::snprintf( buffer, sizeof( buffer ), "%06zu", index );
    return buffer;
}

//---------------------------------------------------------------------------//
// Loop-state fields as attributes: double, string, or int64 for the
// integer and bool fields.
template <class T>
AttributeValue toAttribute( const T& value )
{
    if constexpr ( std::is_same_v<T, double> || std::is_same_v<T, std::string> )
        return value;
    else
        return static_cast<std::int64_t>( value );
}

template <class T>
void fromAttribute( const AttributeValue& attribute, T& value,
                    const std::string& file, const std::string& name )
{
    using Stored = std::conditional_t<std::is_same_v<T, double> ||
                                          std::is_same_v<T, std::string>,
                                      T, std::int64_t>;
    const auto* stored = std::get_if<Stored>( &attribute );
    if ( !stored )
        throw std::runtime_error( "checkpoint '" + file + "': field '" + name +
                                  "' has the wrong type" );
    value = static_cast<T>( *stored );
}
} // namespace

//---------------------------------------------------------------------------//
std::vector<std::string> linkNames( const Hdf5Ops& h5, const hid_t loc,
                                    const std::string& object )
{
    std::vector<std::string> names;
    const H5L_iterate_t collect = []( hid_t, const char* name,
                                      const H5L_info_t*, void* out ) -> herr_t
    {
        static_cast<std::vector<std::string>*>( out )->push_back( name );
        return 0;
    };
    h5.check(
        H5Literate( loc, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names ),
        "H5Literate", object );
    return names;
}

//---------------------------------------------------------------------------//
void writeLoop( const std::string& file, const hid_t root,
                const StageLoopState& loop, AttributeDigest& digest )
{
    Hdf5Ops h5( who, file );
    const hid_t group = h5.open(
        H5Gcreate2( root, "loop", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT ),
        "H5Gcreate2", H5Gclose, "/loop" );
    visitStageLoopState(
        loop,
        [&]( const std::string& name, const auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<StageSummary>> )
            {
                const std::string path = "/loop/" + name;
                const hid_t stages =
                    h5.open( H5Gcreate2( group, name.c_str(), H5P_DEFAULT,
                                         H5P_DEFAULT, H5P_DEFAULT ),
                             "H5Gcreate2", H5Gclose, path );
                for ( std::size_t k = 0; k < value.size(); ++k )
                {
                    const std::string sub = path + "/" + groupName( k );
                    const hid_t stage = h5.open(
                        H5Gcreate2( stages, groupName( k ).c_str(), H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT ),
                        "H5Gcreate2", H5Gclose, sub );
                    visitStageSummary(
                        value[k],
                        [&]( const std::string& field, const auto& v ) {
                            digest.write( h5, stage, sub, field,
                                          toAttribute( v ) );
                        } );
                }
            }
            else
            {
                digest.write( h5, group, "/loop", name, toAttribute( value ) );
            }
        } );
    h5.closeAll();
}

void readLoop( const std::string& file, const hid_t root, StageLoopState& loop,
               AttributeDigest& digest )
{
    Hdf5Ops h5( who, file );
    const hid_t group = h5.open( H5Gopen2( root, "loop", H5P_DEFAULT ),
                                 "H5Gopen2", H5Gclose, "/loop" );
    // Reads attribute `name` of `loc` into `value`.
    const auto read = [&]( const hid_t loc, const std::string& object,
                           const std::string& name, auto& value )
    {
        if ( !h5.hasAttribute( loc, object, name.c_str() ) )
            throw std::runtime_error(
                "checkpoint '" + file + "': missing loop field '" + name +
                "' in " + object +
                " (written by another version of rainslide?)" );
        fromAttribute( digest.read( h5, loc, object, name ), value, file,
                       name );
    };
    visitStageLoopState(
        loop,
        [&]( const std::string& name, auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<StageSummary>> )
            {
                const std::string path = "/loop/" + name;
                const hid_t stages =
                    h5.open( H5Gopen2( group, name.c_str(), H5P_DEFAULT ),
                             "H5Gopen2", H5Gclose, path );
                value.resize( linkNames( h5, stages, path ).size() );
                for ( std::size_t k = 0; k < value.size(); ++k )
                {
                    const std::string sub = path + "/" + groupName( k );
                    const hid_t stage = h5.open(
                        H5Gopen2( stages, groupName( k ).c_str(), H5P_DEFAULT ),
                        "H5Gopen2", H5Gclose, sub );
                    visitStageSummary( value[k],
                                       [&]( const std::string& field, auto& v )
                                       { read( stage, sub, field, v ); } );
                }
            }
            else
                read( group, "/loop", name, value );
        } );
    h5.closeAll();
}

} // namespace Impl
} // namespace mpm
