#include <io/mpm_hdf5.hpp>
#include <io/mpm_json_output.hpp>
#include <io/mpm_safe_file.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <io/mpm_xdmf.hpp>

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <set>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <variant>

namespace mpm
{
namespace
{
using Impl::Hdf5Ops;

// Who reports errors of the snapshot output.
const char* const who = "mpm::SnapshotWriter";

// Extents of a field: [n] (1 component) or [n x components].
std::vector<hsize_t> fieldDims( const hsize_t n, const int components )
{
    if ( components == 1 )
        return { n };
    return { n, static_cast<hsize_t>( components ) };
}

//---------------------------------------------------------------------------//
// Throws std::invalid_argument for bad names, missing data or missing "x".
void checkFields( const int n_points, const std::vector<FieldRef>& fields,
                  const std::vector<IntFieldRef>& int_fields )
{
    const std::string where = "mpm::SnapshotWriter::write: ";
    if ( n_points < 0 )
        throw std::invalid_argument( where + "negative n_points" );
    std::set<std::string> names;
    const auto check = [&]( const std::string& name, const bool bad )
    {
        if ( bad || name.empty() || name == "." ||
             name.find( '/' ) != name.npos || !names.insert( name ).second )
            throw std::invalid_argument(
                where + "invalid, duplicate or empty field '" + name + "'" );
    };
    bool has_x = false;
    for ( const auto& f : fields )
    {
        check( f.name, f.components < 1 || ( n_points > 0 && !f.data ) );
        has_x = has_x || ( f.name == "x" && f.components == 2 );
    }
    for ( const auto& f : int_fields )
        check( f.name, n_points > 0 && !f.data );
    if ( !has_x )
        throw std::invalid_argument(
            where +
            "positions must be a double field \"x\" with 2 components" );
}

} // namespace

//---------------------------------------------------------------------------//
SnapshotWriter::SnapshotWriter( const std::string& out_dir,
                                const std::string& stem )
    : _stem( stem )
{
    preparePaths( out_dir );
    createFile();
}

//---------------------------------------------------------------------------//
SnapshotWriter::SnapshotWriter( const std::string& out_dir,
                                const std::string& stem,
                                const std::string& keep_from,
                                const SnapshotSeriesMark& keep )
    : _stem( stem )
{
    namespace fs = std::filesystem;
    preparePaths( out_dir );
    // The interrupted run's own .partial would be truncated by createFile():
    // move it aside and copy from there.
    std::string source = keep_from;
    std::error_code ec;
    const bool own_partial =
        keep.count > 0 && fs::equivalent( keep_from, _partial_path, ec );
    if ( own_partial )
    {
        source = _partial_path + ".resume";
        if ( std::rename( _partial_path.c_str(), source.c_str() ) != 0 )
        {
            const int error_number = errno;
            throw std::runtime_error(
                "mpm::SnapshotWriter: rename '" + _partial_path + "' -> '" +
                source + "' failed: " + std::strerror( error_number ) );
        }
    }
    try
    {
        createFile();
    }
    catch ( ... )
    {
        if ( own_partial )
            std::rename( source.c_str(), _partial_path.c_str() );
        throw;
    }
    try
    {
        if ( keep.count > 0 )
            copySnapshots( source, keep.count );
    }
    catch ( ... )
    {
        H5Fclose( _file_id );
        std::remove( _partial_path.c_str() );
        if ( own_partial )
            std::rename( source.c_str(), _partial_path.c_str() );
        _finalized = true;
        throw;
    }
    if ( own_partial )
        std::remove( source.c_str() );
}

//---------------------------------------------------------------------------//
void SnapshotWriter::preparePaths( const std::string& out_dir )
{
    namespace fs = std::filesystem;
    if ( _stem.empty() || _stem.find( '/' ) != std::string::npos )
        throw std::invalid_argument( "mpm::SnapshotWriter: invalid stem '" +
                                     _stem + "'" );

    // Create the output folder.
    std::error_code ec;
    fs::create_directories( out_dir, ec );
    if ( ec || !fs::is_directory( out_dir ) )
        throw std::runtime_error(
            "mpm::SnapshotWriter: cannot create output folder '" + out_dir +
            "': " + ( ec ? ec.message() : "not a folder" ) );
    _h5_path = ( fs::path( out_dir ) / ( _stem + ".h5" ) ).string();
    _partial_path = _h5_path + ".partial";
    _xdmf_path = ( fs::path( out_dir ) / ( _stem + ".xdmf" ) ).string();
}

//---------------------------------------------------------------------------//
void SnapshotWriter::createFile()
{
    // Create the file with its root attributes and /snapshots. Unlink what
    // is there and create exclusively: a planted symlink is removed, never
    // followed (O_CREAT | O_EXCL does not follow one).
    Hdf5Ops h5( who, _partial_path );
    removeStale( _partial_path );
    _file_id = h5.check( H5Fcreate( _partial_path.c_str(), H5F_ACC_EXCL,
                                    H5P_DEFAULT, H5P_DEFAULT ),
                         "H5Fcreate", "/" );
    try
    {
        h5.writeAttribute( _file_id, "/", "format",
                           std::string( "rainslide-particles-1" ) );
        h5.writeAttribute( _file_id, "/", "snapshot_count", std::int64_t( 0 ) );
        h5.open( H5Gcreate2( _file_id, "snapshots", H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT ),
                 "H5Gcreate2", H5Gclose, "/snapshots" );
        h5.closeAll();
        h5.check( H5Fflush( _file_id, H5F_SCOPE_GLOBAL ), "H5Fflush", "/" );
    }
    catch ( ... )
    {
        H5Fclose( _file_id );
        std::remove( _partial_path.c_str() );
        throw;
    }
}

//---------------------------------------------------------------------------//
void SnapshotWriter::copySnapshots( const std::string& source,
                                    const long count )
{
    Hdf5Ops in( who, source );
    const hid_t src =
        in.open( H5Fopen( source.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT ),
                 "H5Fopen", H5Fclose, "/" );
    long n_max = 0;
    for ( long s = 0; s < count; ++s )
    {
        const std::string g = "/snapshots/" + snapshotGroupName( s );
        in.check( H5Ocopy( src, g.c_str(), _file_id, g.c_str(), H5P_DEFAULT,
                           H5P_DEFAULT ),
                  "H5Ocopy", g );
        Hdf5Ops h5( who, source );
        const hid_t group = h5.open( H5Gopen2( src, g.c_str(), H5P_DEFAULT ),
                                     "H5Gopen2", H5Gclose, g );
        const auto integer = [&]( const char* name )
        {
            return static_cast<long>(
                std::get<std::int64_t>( h5.readAttribute( group, g, name ) ) );
        };
        XdmfSnapshot record{
            std::get<double>( h5.readAttribute( group, g, "time_s" ) ),
            std::get<std::string>( h5.readAttribute( group, g, "stage" ) ),
            std::get<double>( h5.readAttribute( group, g, "stage_time_s" ) ),
            integer( "step" ),
            integer( "n_points" ),
            {} };
        // In creation order when the group tracks it (files of this
        // writer), else in name order.
        for ( const std::string& name : h5.linkNames( group, g, true ) )
        {
            const std::string path = g + "/" + name;
            const auto dims = h5.datasetDims( src, path );
            const hid_t dset =
                h5.open( H5Dopen2( src, path.c_str(), H5P_DEFAULT ), "H5Dopen2",
                         H5Dclose, path );
            const hid_t type =
                h5.open( H5Dget_type( dset ), "H5Dget_type", H5Tclose, path );
            record.fields.push_back(
                { name, dims.size() > 1 ? static_cast<int>( dims[1] ) : 1,
                  H5Tget_class( type ) == H5T_INTEGER } );
        }
        h5.closeAll();
        n_max = std::max( n_max, record.n_points );
        _records.push_back( std::move( record ) );
    }
    in.closeAll();

    writeVertexIds( n_max );
    Hdf5Ops out( who, _partial_path );
    const std::int64_t complete = count;
    const hid_t attr =
        out.open( H5Aopen( _file_id, "snapshot_count", H5P_DEFAULT ), "H5Aopen",
                  H5Aclose, "/@snapshot_count" );
    out.check( H5Awrite( attr, H5T_NATIVE_INT64, &complete ), "H5Awrite",
               "/@snapshot_count" );
    out.closeAll();
    out.check( H5Fflush( _file_id, H5F_SCOPE_GLOBAL ), "H5Fflush", "/" );
}

//---------------------------------------------------------------------------//
SnapshotSeriesMark SnapshotWriter::mark() const
{
    SnapshotSeriesMark m;
    m.count = static_cast<long>( _records.size() );
    if ( !_records.empty() )
    {
        m.last_step = _records.back().step;
        m.last_time_s = _records.back().time_s;
    }
    return m;
}

//---------------------------------------------------------------------------//
SnapshotWriter::~SnapshotWriter()
{
    try
    {
        finalize();
    }
    catch ( const std::exception& e )
    {
        std::cerr << "mpm::SnapshotWriter: finalize failed: " << e.what()
                  << std::endl;
    }
}

//---------------------------------------------------------------------------//
void SnapshotWriter::write( const double time_s, const std::string& stage,
                            const double stage_time_s, const long step,
                            const int n_points,
                            const std::vector<FieldRef>& fields,
                            const std::vector<IntFieldRef>& int_fields )
{
    if ( _finalized )
        throw std::logic_error( "mpm::SnapshotWriter::write: '" +
                                _partial_path + "' was already finalized" );
    checkFields( n_points, fields, int_fields );

    Hdf5Ops h5( who, _partial_path );
    const std::string g = "/snapshots/" + snapshotGroupName( _records.size() );
    const auto n = static_cast<hsize_t>( n_points );
    try
    {
        // Group, its attributes and one dataset per field.
        // Track the fields' creation order (kept when a restart copies it).
        const hid_t gcpl =
            h5.open( H5Pcreate( H5P_GROUP_CREATE ), "H5Pcreate", H5Pclose, g );
        h5.check( H5Pset_link_creation_order( gcpl, H5P_CRT_ORDER_TRACKED |
                                                        H5P_CRT_ORDER_INDEXED ),
                  "H5Pset_link_creation_order", g );
        const hid_t group = h5.open(
            H5Gcreate2( _file_id, g.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT ),
            "H5Gcreate2", H5Gclose, g );
        h5.writeAttribute( group, g, "time_s", time_s );
        h5.writeAttribute( group, g, "stage", stage );
        h5.writeAttribute( group, g, "stage_time_s", stage_time_s );
        h5.writeAttribute( group, g, "step", std::int64_t( step ) );
        h5.writeAttribute( group, g, "n_points", std::int64_t( n_points ) );
        for ( const auto& f : fields )
            h5.writeDataset( group, g + "/" + f.name, H5T_IEEE_F64LE,
                             H5T_NATIVE_DOUBLE, fieldDims( n, f.components ),
                             f.data, f.unit );
        for ( const auto& f : int_fields )
            h5.writeDataset( group, g + "/" + f.name, H5T_STD_I32LE,
                             H5T_NATIVE_INT, { n }, f.data, "1" );
        h5.closeAll();
        writeVertexIds( n_points );

        // Count the snapshot as complete, then flush to disk.
        const std::int64_t count = _records.size() + 1;
        const hid_t attr =
            h5.open( H5Aopen( _file_id, "snapshot_count", H5P_DEFAULT ),
                     "H5Aopen", H5Aclose, "/@snapshot_count" );
        h5.check( H5Awrite( attr, H5T_NATIVE_INT64, &count ), "H5Awrite",
                  "/@snapshot_count" );
        h5.closeAll();
        h5.check( H5Fflush( _file_id, H5F_SCOPE_GLOBAL ), "H5Fflush", g );
    }
    catch ( ... )
    {
        // Drop the incomplete group so the next write() can reuse its name;
        // the file may be truncated (a full disk): never publish it.
        _write_failed = true;
        H5Ldelete( _file_id, g.c_str(), H5P_DEFAULT );
        H5Eclear2( H5E_DEFAULT );
        throw;
    }
    XdmfSnapshot record{ time_s, stage, stage_time_s, step, n_points, {} };
    for ( const auto& f : fields )
        record.fields.push_back( { f.name, f.components, false } );
    for ( const auto& f : int_fields )
        record.fields.push_back( { f.name, 1, true } );
    _records.push_back( std::move( record ) );
}

//---------------------------------------------------------------------------//
void SnapshotWriter::writeVertexIds( const long n_points )
{
    // /vertex_ids = 0..n_max-1, the Polyvertex connectivity of every grid;
    // replaced by a longer one when a snapshot has more points.
    if ( n_points <= _vertex_id_count )
        return;
    if ( _vertex_id_count > 0 )
        Hdf5Ops( who, _partial_path )
            .check( H5Ldelete( _file_id, "/vertex_ids", H5P_DEFAULT ),
                    "H5Ldelete", "/vertex_ids" );
    _vertex_id_count = 0;
    std::vector<int> ids( n_points );
    std::iota( ids.begin(), ids.end(), 0 );
    Hdf5Ops( who, _partial_path )
        .writeDataset( _file_id, "/vertex_ids", H5T_STD_I32LE, H5T_NATIVE_INT,
                       { ids.size() }, ids.data(), "1" );
    _vertex_id_count = n_points;
}

//---------------------------------------------------------------------------//
void SnapshotWriter::finalize()
{
    if ( _finalized )
        return;
    _finalized = true;

    // Close the file, then publish it under its final name.
    const herr_t closed = H5Fclose( _file_id );
    if ( _write_failed )
        throw std::runtime_error(
            "mpm::SnapshotWriter::finalize: a snapshot write failed (disk "
            "full?); '" +
            _partial_path + "' is incomplete and was not renamed to '" +
            _h5_path + "' (an earlier one is kept)" );
    Hdf5Ops( who, _partial_path ).check( closed, "H5Fclose", "/" );
    if ( std::rename( _partial_path.c_str(), _h5_path.c_str() ) != 0 )
    {
        const int error_number = errno;
        throw std::runtime_error(
            "mpm::SnapshotWriter::finalize: rename '" + _partial_path +
            "' -> '" + _h5_path +
            "' failed: " + std::strerror( error_number ) );
    }
    writeTextAtomically( _xdmf_path,
                         xdmfText( _stem, _records, _vertex_id_count ) );
}

} // namespace mpm
