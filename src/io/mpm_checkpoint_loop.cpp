#include <io/mpm_checkpoint_loop.hpp>
#include <io/mpm_stage_state_json.hpp>

#include <stdexcept>

namespace mpm
{
namespace Impl
{
namespace
{
const char* const who = "mpm::Checkpoint";
//! The attribute of /loop holding the loop state's JSON text.
const char* const json_name = "json";
} // namespace

//---------------------------------------------------------------------------//
void writeLoop( const std::string& file, const hid_t root,
                const StageLoopState& loop, AttributeDigest& digest )
{
    Hdf5Ops h5( who, file );
    const hid_t group = h5.open(
        H5Gcreate2( root, "loop", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT ),
        "H5Gcreate2", H5Gclose, "/loop" );
    digest.write( h5, group, "/loop", json_name, stageLoopStateJson( loop ) );
    h5.closeAll();
}

void readLoop( const std::string& file, const hid_t root, StageLoopState& loop,
               AttributeDigest& digest )
{
    Hdf5Ops h5( who, file );
    const hid_t group = h5.open( H5Gopen2( root, "loop", H5P_DEFAULT ),
                                 "H5Gopen2", H5Gclose, "/loop" );
    if ( !h5.hasAttribute( group, "/loop", json_name ) )
        throw std::runtime_error( "checkpoint '" + file +
                                  "': /loop has no attribute '" + json_name +
                                  "' (written by another version of "
                                  "rainslide?)" );
    const AttributeValue value = digest.read( h5, group, "/loop", json_name );
    const auto* text = std::get_if<std::string>( &value );
    if ( !text )
        throw std::runtime_error( "checkpoint '" + file + "': /loop@" +
                                  json_name + " is not a string" );
    loop = parseStageLoopState( *text, file );
    h5.closeAll();
}

} // namespace Impl
} // namespace mpm
