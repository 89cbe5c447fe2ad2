#include <io/mpm_attribute_digest.hpp>
#include <io/mpm_case_fingerprint.hpp>
#include <io/mpm_checkpoint.hpp>
#include <io/mpm_checkpoint_loop.hpp>
#include <io/mpm_hdf5.hpp>
#include <io/mpm_safe_file.hpp>
#include <mpm_config.hpp>

#include <hdf5.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <type_traits>

#include <fcntl.h>
#include <unistd.h>

namespace mpm
{
namespace
{
using Impl::AttributeDigest;
using Impl::AttributeValue;
using Impl::Hdf5Ops;
using Impl::readLoop;
using Impl::writeLoop;

const char* const who = "mpm::Checkpoint";
const char* const format_name = "rainslide-checkpoint-2";
//! Root attribute holding the AttributeDigest of the state's attributes.
const char* const digest_name = "attribute_digest";

//---------------------------------------------------------------------------//
/*!
  Writes `data` (dims, mem_type) as dataset `path` of `loc`; a non-empty
  one in one chunk with a Fletcher-32 checksum, so H5Dread refuses it when
  damaged (a flipped byte was restored silently before).
*/
void writeChecked( const Hdf5Ops& h5, const hid_t loc, const std::string& path,
                   const hid_t file_type, const hid_t mem_type,
                   const std::vector<hsize_t>& dims, const void* data,
                   const hid_t lcpl = H5P_DEFAULT )
{
    Hdf5Ops ops( who, h5.file() );
    hsize_t count = 1;
    for ( const hsize_t d : dims )
        count *= d;
    const hid_t space =
        ops.open( H5Screate_simple( int( dims.size() ), dims.data(), nullptr ),
                  "H5Screate_simple", H5Sclose, path );
    const hid_t dcpl = ops.open( H5Pcreate( H5P_DATASET_CREATE ), "H5Pcreate",
                                 H5Pclose, path );
    if ( count > 0 )
    {
        ops.check( H5Pset_chunk( dcpl, int( dims.size() ), dims.data() ),
                   "H5Pset_chunk", path );
        ops.check( H5Pset_fletcher32( dcpl ), "H5Pset_fletcher32", path );
    }
    const hid_t dset = ops.open( H5Dcreate2( loc, path.c_str(), file_type,
                                             space, lcpl, dcpl, H5P_DEFAULT ),
                                 "H5Dcreate2", H5Dclose, path );
    if ( count > 0 )
        ops.check(
            H5Dwrite( dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data ),
            "H5Dwrite", path );
    ops.closeAll();
}

// Writes `data` as the checked dataset `path` of `loc` (1D).
template <class T>
void writeVector( const Hdf5Ops& h5, const hid_t loc, const std::string& path,
                  const std::vector<T>& data )
{
    if constexpr ( std::is_same_v<T, double> )
        writeChecked( h5, loc, path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                      { data.size() }, data.data() );
    else
        writeChecked( h5, loc, path, H5T_STD_I32LE, H5T_NATIVE_INT,
                      { data.size() }, data.data() );
}

template <class T>
std::vector<T> readVector( const Hdf5Ops& h5, const hid_t loc,
                           const std::string& path )
{
    std::size_t count = 1;
    for ( const hsize_t d : h5.datasetDims( loc, path ) )
        count *= d;
    std::vector<T> data( count );
    hid_t type = H5T_NATIVE_INT;
    if constexpr ( std::is_same_v<T, double> )
        type = H5T_NATIVE_DOUBLE;
    else if constexpr ( std::is_same_v<T, unsigned char> )
        type = H5T_NATIVE_UCHAR;
    h5.readDataset( loc, path, type, data.data() );
    return data;
}

//---------------------------------------------------------------------------//
void writeArrays( const std::string& file, const hid_t root,
                  const std::vector<CheckpointArray>& arrays )
{
    Hdf5Ops h5( who, file );
    const hid_t lcpl = h5.open( H5Pcreate( H5P_LINK_CREATE ), "H5Pcreate",
                                H5Pclose, "/state" );
    h5.check( H5Pset_create_intermediate_group( lcpl, 1 ),
              "H5Pset_create_intermediate_group", "/state" );
    h5.open( H5Gcreate2( root, "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT ),
             "H5Gcreate2", H5Gclose, "/state" );
    for ( const CheckpointArray& a : arrays )
    {
        const std::vector<hsize_t> dims( a.dims.begin(), a.dims.end() );
        writeChecked( h5, root, "/state/" + a.name,
                      a.integer ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                      a.integer ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, dims,
                      a.integer ? static_cast<const void*>( a.integers.data() )
                                : a.reals.data(),
                      lcpl );
    }
    h5.closeAll();
}

std::vector<CheckpointArray> readArrays( const std::string& file,
                                         const hid_t root )
{
    Hdf5Ops h5( who, file );
    std::vector<CheckpointArray> arrays;
    const hid_t state = h5.open( H5Gopen2( root, "state", H5P_DEFAULT ),
                                 "H5Gopen2", H5Gclose, "/state" );
    for ( const std::string& group_name : h5.linkNames( state, "/state" ) )
    {
        const std::string group_path = "/state/" + group_name;
        const hid_t group =
            h5.open( H5Gopen2( state, group_name.c_str(), H5P_DEFAULT ),
                     "H5Gopen2", H5Gclose, group_path );
        for ( const std::string& name : h5.linkNames( group, group_path ) )
        {
            const std::string path = group_path + "/" + name;
            CheckpointArray a;
            a.name = group_name + "/" + name;
            for ( const hsize_t d : h5.datasetDims( root, path ) )
                a.dims.push_back( d );
            const hid_t dset =
                h5.open( H5Dopen2( root, path.c_str(), H5P_DEFAULT ),
                         "H5Dopen2", H5Dclose, path );
            const hid_t type =
                h5.open( H5Dget_type( dset ), "H5Dget_type", H5Tclose, path );
            a.integer = H5Tget_class( type ) == H5T_INTEGER;
            if ( a.integer )
                a.integers = readVector<int>( h5, root, path );
            else
                a.reals = readVector<double>( h5, root, path );
            arrays.push_back( std::move( a ) );
        }
    }
    h5.closeAll();
    return arrays;
}

//---------------------------------------------------------------------------//
// Flushes a file (or folder) to disk; throws naming it.
void syncToDisk( const std::string& path, const int flags )
{
    const int fd = ::open( path.c_str(), flags | O_CLOEXEC );
    if ( fd < 0 || ::fsync( fd ) != 0 )
    {
        const int error_number = errno;
        if ( fd >= 0 )
            ::close( fd );
        throw std::runtime_error(
            "mpm::writeCheckpoint: fsync of '" + path +
            "' failed: " + std::strerror( error_number ) );
    }
    ::close( fd );
}

// Writes the whole checkpoint to a new file `path`.
void writeFile( const std::string& path, const Checkpoint& c )
{
    Hdf5Ops h5( who, path );
    // Exclusive: a symlink planted at path is removed, never followed.
    removeStale( path );
    // The 1.10 file format: superblock, object headers, B-trees and the
    // chunk index carry checksums, so a damaged one is refused like a
    // damaged dataset. (In the 1.8 format a dataset's chunk index is a
    // version 1 B-tree without one: a flipped bit in it lost the chunk, and
    // the dataset read back as its fill value, all zeros, unchecked.)
    const hid_t fapl =
        h5.open( H5Pcreate( H5P_FILE_ACCESS ), "H5Pcreate", H5Pclose, "/" );
    h5.check( H5Pset_libver_bounds( fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST ),
              "H5Pset_libver_bounds", "/" );
    const hid_t file =
        h5.open( H5Fcreate( path.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, fapl ),
                 "H5Fcreate", H5Fclose, "/" );
    const CheckpointIdentity& id = c.identity;
    const std::vector<std::pair<const char*, AttributeValue>> attributes = {
        { "format", std::string( format_name ) },
        { "rainslide_version", std::string( RAINSLIDE_VERSION ) },
        { "case_name", id.case_name },
        { "case_file", id.case_file },
        { "case_hash", hashText( fnv1aHash( id.case_fingerprint ) ) },
        { "analysis", id.analysis },
        { "n_points", std::int64_t( id.num_points ) },
        { "backend", id.backend },
        { "threads", std::int64_t( id.threads ) },
        { "time_s", c.time_s },
        { "step", std::int64_t( c.step ) },
        { "num_removed", std::int64_t( c.num_removed ) },
        { "grid_num_active", std::int64_t( c.grid_num_active ) },
        { "wall_s", c.wall_s },
        { "snapshot_count", std::int64_t( c.snapshots.count ) },
        { "last_snapshot_step", std::int64_t( c.snapshots.last_step ) },
        { "last_snapshot_time_s", c.snapshots.last_time_s } };
    AttributeDigest digest;
    for ( const auto& [name, value] : attributes )
        digest.write( h5, file, "/", name, value );
    const std::string& text = id.case_fingerprint;
    writeChecked( h5, file, "case_fingerprint", H5T_STD_U8LE, H5T_NATIVE_UCHAR,
                  { text.size() }, text.data() );

    writeArrays( path, file, c.arrays );

    const hid_t conditions = h5.open(
        H5Gcreate2( file, "conditions", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT ),
        "H5Gcreate2", H5Gclose, "/conditions" );
    std::vector<int> sizes, members;
    for ( const auto& group : c.load_groups )
    {
        sizes.push_back( static_cast<int>( group.size() ) );
        members.insert( members.end(), group.begin(), group.end() );
    }
    writeVector( h5, conditions, "load_counts", c.load_counts );
    writeVector( h5, conditions, "load_group_sizes", sizes );
    writeVector( h5, conditions, "load_group_members", members );
    writeVector( h5, conditions, "inflow_volumes", c.inflow_volumes );
    writeVector( h5, conditions, "inflow_lengths_m", c.inflow_lengths_m );
    digest.write( h5, conditions, "/conditions", "next_surface_update_s",
                  c.next_surface_update_s );

    writeLoop( path, file, c.loop, digest );
    h5.writeAttribute( file, "/", digest_name, digest.hex() );
    h5.closeAll();
}

} // namespace

//---------------------------------------------------------------------------//
const CheckpointArray* Checkpoint::find( const std::string& name ) const
{
    for ( const CheckpointArray& a : arrays )
        if ( a.name == name )
            return &a;
    return nullptr;
}

std::string checkpointPath( const std::string& out_dir )
{
    return ( std::filesystem::path( out_dir ) / "checkpoint.h5" ).string();
}

//---------------------------------------------------------------------------//
void writeCheckpoint( const std::string& path, const Checkpoint& checkpoint )
{
    const std::string partial = path + ".partial";
    try
    {
        writeFile( partial, checkpoint );
        syncToDisk( partial, O_RDONLY );
    }
    catch ( ... )
    {
        std::remove( partial.c_str() );
        throw;
    }
    if ( std::rename( partial.c_str(), path.c_str() ) != 0 )
    {
        const int error_number = errno;
        std::remove( partial.c_str() );
        throw std::runtime_error(
            "mpm::writeCheckpoint: rename '" + partial + "' -> '" + path +
            "' failed: " + std::strerror( error_number ) );
    }
    // Make the rename itself durable.
    const auto folder = std::filesystem::path( path ).parent_path();
    syncToDisk( folder.empty() ? "." : folder.string(),
                O_RDONLY | O_DIRECTORY );
}

//---------------------------------------------------------------------------//
Checkpoint readCheckpoint( const std::string& path )
{
    if ( !std::filesystem::exists( path ) )
        throw std::runtime_error( "checkpoint '" + path + "' does not exist" );
    Hdf5Ops h5( who, path );
    const hid_t file =
        h5.open( H5Fopen( path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT ),
                 "H5Fopen", H5Fclose, "/" );
    const bool is_checkpoint = h5.hasAttribute( file, "/", "format" ) &&
                               h5.readAttribute( file, "/", "format" ) ==
                                   AttributeValue( std::string( format_name ) );
    if ( !is_checkpoint )
        throw std::runtime_error( "'" + path +
                                  "' is not a rainslide checkpoint (" +
                                  format_name + ")" );
    Checkpoint c;
    AttributeDigest digest;
    // Reads a root attribute and takes it into the digest.
    const auto attribute = [&]( const char* name )
    { return digest.read( h5, file, "/", name ); };
    const auto text = [&]( const char* name )
    { return std::get<std::string>( attribute( name ) ); };
    const auto integer = [&]( const char* name )
    { return std::get<std::int64_t>( attribute( name ) ); };
    const auto real = [&]( const char* name )
    { return std::get<double>( attribute( name ) ); };
    // The attributes the digest covers but the state does not use.
    for ( const char* name : { "format", "rainslide_version", "case_hash" } )
        attribute( name );
    CheckpointIdentity& id = c.identity;
    id.case_name = text( "case_name" );
    id.case_file = text( "case_file" );
    id.analysis = text( "analysis" );
    id.num_points = integer( "n_points" );
    id.backend = text( "backend" );
    id.threads = static_cast<int>( integer( "threads" ) );
    const auto fingerprint =
        readVector<unsigned char>( h5, file, "case_fingerprint" );
    id.case_fingerprint.assign( fingerprint.begin(), fingerprint.end() );
    c.time_s = real( "time_s" );
    c.step = integer( "step" );
    c.num_removed = static_cast<int>( integer( "num_removed" ) );
    c.grid_num_active = static_cast<int>( integer( "grid_num_active" ) );
    c.wall_s = real( "wall_s" );
    c.snapshots.count = integer( "snapshot_count" );
    c.snapshots.last_step = integer( "last_snapshot_step" );
    c.snapshots.last_time_s = real( "last_snapshot_time_s" );

    c.arrays = readArrays( path, file );

    const hid_t conditions =
        h5.open( H5Gopen2( file, "conditions", H5P_DEFAULT ), "H5Gopen2",
                 H5Gclose, "/conditions" );
    c.load_counts = readVector<int>( h5, conditions, "load_counts" );
    const auto sizes = readVector<int>( h5, conditions, "load_group_sizes" );
    const auto members =
        readVector<int>( h5, conditions, "load_group_members" );
    std::size_t at = 0;
    for ( std::size_t g = 0; g < sizes.size(); ++g )
    {
        const int size = sizes[g];
        if ( size < 0 || at + size > members.size() )
            throw std::runtime_error(
                "checkpoint '" + path + "': conditions/load_group_sizes[" +
                std::to_string( g ) +
                "]: expected group sizes >= 0 that add up to the length of "
                "conditions/load_group_members, " +
                std::to_string( members.size() ) + ", found " +
                std::to_string( size ) );
        c.load_groups.emplace_back( members.begin() + at,
                                    members.begin() + at + size );
        at += size;
    }
    if ( at != members.size() )
        throw std::runtime_error(
            "checkpoint '" + path +
            "': conditions/load_group_sizes: expected group sizes that add "
            "up to the length of conditions/load_group_members, " +
            std::to_string( members.size() ) + ", found a sum of " +
            std::to_string( at ) );
    c.inflow_volumes = readVector<double>( h5, conditions, "inflow_volumes" );
    c.inflow_lengths_m =
        readVector<double>( h5, conditions, "inflow_lengths_m" );
    c.next_surface_update_s = std::get<double>(
        digest.read( h5, conditions, "/conditions", "next_surface_update_s" ) );

    readLoop( path, file, c.loop, digest );
    const bool has_digest = h5.hasAttribute( file, "/", digest_name );
    if ( !has_digest || h5.readAttribute( file, "/", digest_name ) !=
                            AttributeValue( digest.hex() ) )
        throw std::runtime_error(
            "checkpoint '" + path + "': " +
            ( has_digest ? "its attributes (time, step, stage loop state) do "
                           "not match their checksum: the file is damaged"
                         : "it has no attribute checksum (written by "
                           "another version of rainslide?)" ) );
    h5.closeAll();
    return c;
}

//---------------------------------------------------------------------------//
std::string checkpointMismatch( const Checkpoint& checkpoint,
                                const std::string& checkpoint_file,
                                const CheckpointIdentity& now )
{
    const CheckpointIdentity& then = checkpoint.identity;
    std::string issues;
    if ( then.case_name != now.case_name )
        issues += "  case name: '" + then.case_name + "' in the checkpoint, '" +
                  now.case_name + "' now\n";
    if ( then.analysis != now.analysis )
        issues += "  case.analysis: " + then.analysis + " in the checkpoint, " +
                  now.analysis + " now\n";
    if ( then.num_points != now.num_points )
        issues += "  number of material points: " +
                  std::to_string( then.num_points ) + " in the checkpoint, " +
                  std::to_string( now.num_points ) + " now\n";
    if ( fnv1aHash( then.case_fingerprint ) !=
         fnv1aHash( now.case_fingerprint ) )
        issues += "  the case's keys differ (case hash " +
                  hashText( fnv1aHash( then.case_fingerprint ) ) +
                  " in the checkpoint, " +
                  hashText( fnv1aHash( now.case_fingerprint ) ) + " now):\n" +
                  fingerprintDifferences( then.case_fingerprint,
                                          now.case_fingerprint );
    if ( issues.empty() )
        return "";
    return "cannot restart from checkpoint '" + checkpoint_file +
           "': it was written for case file '" + then.case_file +
           "', which differs from '" + now.case_file + "':\n" + issues +
           "A checkpoint continues only the unchanged case it was written "
           "for (solver.checkpoint_interval_s may change).";
}

} // namespace mpm
