#include <io/mpm_json_output.hpp>
#include <io/mpm_snapshot_writer.hpp>

#include <hdf5.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <system_error>
#include <type_traits>

static_assert( std::is_same<hid_t, std::int64_t>::value,
               "SnapshotWriter stores hid_t as std::int64_t (HDF5 >= 1.10)" );

namespace mpm
{
namespace
{
//---------------------------------------------------------------------------//
// Collects HDF5's error descriptions, innermost first.
herr_t collectError( unsigned, const H5E_error2_t* err, void* client )
{
    if ( err != nullptr && err->desc != nullptr )
        static_cast<std::vector<std::string>*>( client )->emplace_back(
            err->desc );
    return 0;
}

// " (HDF5: <API-level message>; <innermost message>)" or "".
std::string hdf5ErrorDetail()
{
    std::vector<std::string> msgs;
    if ( H5Ewalk2( H5E_DEFAULT, H5E_WALK_UPWARD, collectError, &msgs ) < 0 ||
         msgs.empty() )
        return "";
    H5Eclear2( H5E_DEFAULT );
    return " (HDF5: " + msgs.back() +
           ( msgs.size() > 1 ? "; " + msgs.front() : "" ) + ")";
}

//---------------------------------------------------------------------------//
// Turns HDF5's automatic error printing off for one scope.
class SilenceHdf5Errors
{
  public:
    SilenceHdf5Errors()
        : _saved( H5Eget_auto2( H5E_DEFAULT, &_func, &_data ) >= 0 )
    {
        H5Eset_auto2( H5E_DEFAULT, nullptr, nullptr );
    }
    ~SilenceHdf5Errors()
    {
        if ( _saved )
            H5Eset_auto2( H5E_DEFAULT, _func, _data );
    }

  private:
    H5E_auto2_t _func = nullptr;
    void* _data = nullptr;
    bool _saved;
};

//---------------------------------------------------------------------------//
// Checks an HDF5 return value; the message names file, object, operation.
struct Hdf5Check
{
    std::string file;

    template <class T>
    T operator()( const T status, const char* operation,
                  const std::string& object ) const
    {
        if ( status < 0 )
            throw std::runtime_error(
                "mpm::SnapshotWriter: " + std::string( operation ) +
                " failed for '" + object + "' in file '" + file + "'" +
                hdf5ErrorDetail() );
        return status;
    }
};

//---------------------------------------------------------------------------//
// Owns one hid_t: the opening call and close() are checked; the destructor
// (error path only) closes silently.
class Handle
{
  public:
    Handle( const Hdf5Check& check, const hid_t id, const char* operation,
            herr_t ( *closer )( hid_t ), std::string object )
        : _check( check )
        , _id( check( id, operation, object ) )
        , _closer( closer )
        , _object( std::move( object ) )
    {
    }
    ~Handle()
    {
        if ( _id >= 0 )
            _closer( _id );
    }
    Handle( const Handle& ) = delete;
    Handle& operator=( const Handle& ) = delete;

    hid_t get() const { return _id; }
    void close()
    {
        const hid_t id = _id;
        _id = -1;
        _check( _closer( id ), "close", _object );
    }

  private:
    const Hdf5Check& _check;
    hid_t _id;
    herr_t ( *_closer )( hid_t );
    std::string _object;
};

//---------------------------------------------------------------------------//
void writeAttribute( const Hdf5Check& check, const hid_t loc,
                     const std::string& object, const char* name,
                     const hid_t file_type, const hid_t mem_type,
                     const void* value )
{
    const std::string where = object + "@" + name;
    Handle space( check, H5Screate( H5S_SCALAR ), "H5Screate", H5Sclose,
                  where );
    Handle attr( check,
                 H5Acreate2( loc, name, file_type, space.get(), H5P_DEFAULT,
                             H5P_DEFAULT ),
                 "H5Acreate2", H5Aclose, where );
    check( H5Awrite( attr.get(), mem_type, value ), "H5Awrite", where );
    attr.close();
    space.close();
}

// Fixed-length, null-terminated UTF-8 string attribute.
void writeStringAttribute( const Hdf5Check& check, const hid_t loc,
                           const std::string& object, const char* name,
                           const std::string& value )
{
    const std::string where = object + "@" + name;
    Handle type( check, H5Tcopy( H5T_C_S1 ), "H5Tcopy", H5Tclose, where );
    check( H5Tset_size( type.get(), value.size() + 1 ), "H5Tset_size", where );
    check( H5Tset_strpad( type.get(), H5T_STR_NULLTERM ), "H5Tset_strpad",
           where );
    check( H5Tset_cset( type.get(), H5T_CSET_UTF8 ), "H5Tset_cset", where );
    writeAttribute( check, loc, object, name, type.get(), type.get(),
                    value.c_str() );
    type.close();
}

// Dataset [n] (1 component) or [n x components] with a "unit" attribute.
void writeDataset( const Hdf5Check& check, const hid_t group,
                   const std::string& path, const std::string& name,
                   const hid_t file_type, const hid_t mem_type,
                   const hsize_t n_points, const int components,
                   const void* data, const std::string& unit )
{
    const hsize_t dims[2] = { n_points, static_cast<hsize_t>( components ) };
    Handle space( check,
                  H5Screate_simple( components == 1 ? 1 : 2, dims, nullptr ),
                  "H5Screate_simple", H5Sclose, path );
    Handle dset( check,
                 H5Dcreate2( group, name.c_str(), file_type, space.get(),
                             H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT ),
                 "H5Dcreate2", H5Dclose, path );
    if ( n_points > 0 )
        check( H5Dwrite( dset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         data ),
               "H5Dwrite", path );
    writeStringAttribute( check, dset.get(), path, "unit", unit );
    dset.close();
    space.close();
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
    bool has_x = false;
    const auto check = [&]( const std::string& name, const bool bad )
    {
        if ( name.empty() || name == "." || name.find( '/' ) != name.npos ||
             !names.insert( name ).second || bad )
            throw std::invalid_argument( where +
                                         "invalid, duplicate or "
                                         "empty field '" +
                                         name + "'" );
    };
    for ( const auto& f : fields )
    {
        check( f.name, f.components < 1 || ( n_points > 0 && !f.data ) );
        has_x = has_x || ( f.name == "x" && f.components == 2 );
    }
    for ( const auto& f : int_fields )
        check( f.name, n_points > 0 && !f.data );
    if ( !has_x )
        throw std::invalid_argument( where + "positions must be a double "
                                             "field \"x\" with 2 components" );
}

//---------------------------------------------------------------------------//
std::string xmlEscape( const std::string& text )
{
    const std::string special = "&<>\"'";
    const char* const entities[] = { "&amp;", "&lt;", "&gt;", "&quot;",
                                     "&apos;" };
    std::string out;
    for ( const char c : text )
    {
        const auto k = special.find( c );
        out += k == std::string::npos ? std::string( 1, c ) : entities[k];
    }
    return out;
}

// Replaces each @key@ in `text` in one pass (values are not rescanned).
std::string fill( const std::string& text,
                  const std::map<std::string, std::string>& values )
{
    std::string out;
    std::size_t i = 0;
    for ( std::size_t at; ( at = text.find( '@', i ) ) != std::string::npos; )
    {
        const std::size_t end = text.find( '@', at + 1 );
        out += text.substr( i, at - i ) +
               values.at( text.substr( at + 1, end - at - 1 ) );
        i = end + 1;
    }
    return out + text.substr( i );
}

// XDMF text of one snapshot and of one field (see fill()).
const char* const grid_xdmf =
    R"(      <Grid Name="snapshot_@name@" GridType="Uniform">
        <Time Value="@time@"/>
        <Information Name="stage" Value="@stage@"/>
        <Topology TopologyType="Polyvertex" NumberOfElements="@n@" NodesPerElement="1">
          <DataItem ItemType="HyperSlab" Dimensions="@n@" Type="HyperSlab">
            <DataItem Dimensions="3 1" Format="XML">0 1 @n@</DataItem>
            <DataItem Dimensions="@n_ids@" NumberType="Int" Precision="4" Format="HDF">@h5@:/vertex_ids</DataItem>
          </DataItem>
        </Topology>
@fields@        <Attribute Name="stage_time_s" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Float" Precision="8" Format="XML">@stage_time@</DataItem>
        </Attribute>
        <Attribute Name="step" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Int" Precision="8" Format="XML">@step@</DataItem>
        </Attribute>
      </Grid>
)";
const char* const field_xdmf = R"(        <@element@ @kind@>
          <DataItem Dimensions="@dims@" NumberType="@type@" Format="HDF">@path@</DataItem>
        </@element@>
)";

// Shortest decimal text that reads back as the same double.
std::string formatDouble( const double value )
{
    char buffer[64];
    const auto end = std::to_chars( buffer, buffer + sizeof( buffer ), value );
    return std::string( buffer, end.ptr );
}

std::string snapshotName( const std::size_t index )
{
    char buffer[32];
    std::snprintf( buffer, sizeof( buffer ), "%06zu", index );
    return buffer;
}

} // namespace

//---------------------------------------------------------------------------//
SnapshotWriter::SnapshotWriter( const std::string& out_dir,
                                const std::string& stem )
    : _stem( stem )
{
    namespace fs = std::filesystem;
    if ( stem.empty() || stem.find( '/' ) != std::string::npos )
        throw std::invalid_argument( "mpm::SnapshotWriter: invalid stem '" +
                                     stem + "'" );

    // Create the output folder.
    std::error_code ec;
    fs::create_directories( out_dir, ec );
    if ( ec || !fs::is_directory( out_dir ) )
        throw std::runtime_error(
            "mpm::SnapshotWriter: cannot create output folder '" + out_dir +
            "': " + ( ec ? ec.message() : "not a folder" ) );
    _h5_path = ( fs::path( out_dir ) / ( stem + ".h5" ) ).string();
    _partial_path = _h5_path + ".partial";
    _xdmf_path = ( fs::path( out_dir ) / ( stem + ".xdmf" ) ).string();

    // Create the file with its root attributes and /snapshots.
    SilenceHdf5Errors silence;
    const Hdf5Check check{ _partial_path };
    _file_id = check( H5Fcreate( _partial_path.c_str(), H5F_ACC_TRUNC,
                                 H5P_DEFAULT, H5P_DEFAULT ),
                      "H5Fcreate", "/" );
    try
    {
        writeStringAttribute( check, _file_id, "/", "format",
                              "rainslide-particles-1" );
        const std::int64_t zero = 0;
        writeAttribute( check, _file_id, "/", "snapshot_count", H5T_STD_I64LE,
                        H5T_NATIVE_INT64, &zero );
        Handle( check,
                H5Gcreate2( _file_id, "snapshots", H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT ),
                "H5Gcreate2", H5Gclose, "/snapshots" )
            .close();

        check( H5Fflush( _file_id, H5F_SCOPE_GLOBAL ), "H5Fflush", "/" );
    }
    catch ( ... )
    {
        H5Fclose( _file_id );
        std::remove( _partial_path.c_str() );
        throw;
    }
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
    catch ( ... )
    {
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

    SilenceHdf5Errors silence;
    const Hdf5Check check{ _partial_path };
    SnapshotRecord record{ time_s, stage, stage_time_s, step, n_points, {} };
    const std::string g = "/snapshots/" + snapshotName( _records.size() );
    const auto n = static_cast<hsize_t>( n_points );
    try
    {
        // Group and its attributes.
        Handle group( check,
                      H5Gcreate2( _file_id, g.c_str(), H5P_DEFAULT, H5P_DEFAULT,
                                  H5P_DEFAULT ),
                      "H5Gcreate2", H5Gclose, g );
        const std::int64_t step64 = step, n64 = n_points;
        const auto attr = [&]( const char* key, const double* value_f64,
                               const std::int64_t* value_i64 )
        {
            writeAttribute( check, group.get(), g, key,
                            value_f64 ? H5T_IEEE_F64LE : H5T_STD_I64LE,
                            value_f64 ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64,
                            value_f64 ? static_cast<const void*>( value_f64 )
                                      : value_i64 );
        };
        attr( "time_s", &time_s, nullptr );
        writeStringAttribute( check, group.get(), g, "stage", stage );
        attr( "stage_time_s", &stage_time_s, nullptr );
        attr( "step", nullptr, &step64 );
        attr( "n_points", nullptr, &n64 );

        // One dataset per field.
        for ( const auto& f : fields )
        {
            writeDataset( check, group.get(), g + "/" + f.name, f.name,
                          H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, f.components,
                          f.data, f.unit );
            record.fields.push_back( { f.name, f.components, false } );
        }
        for ( const auto& f : int_fields )
        {
            writeDataset( check, group.get(), g + "/" + f.name, f.name,
                          H5T_STD_I32LE, H5T_NATIVE_INT, n, 1, f.data, "1" );
            record.fields.push_back( { f.name, 1, true } );
        }
        group.close();
        writeVertexIds( n_points );

        // Count the snapshot as complete, then flush to disk.
        const std::int64_t count = _records.size() + 1;
        Handle attr( check, H5Aopen( _file_id, "snapshot_count", H5P_DEFAULT ),
                     "H5Aopen", H5Aclose, "/@snapshot_count" );
        check( H5Awrite( attr.get(), H5T_NATIVE_INT64, &count ), "H5Awrite",
               "/@snapshot_count" );
        attr.close();
        check( H5Fflush( _file_id, H5F_SCOPE_GLOBAL ), "H5Fflush", g );
    }
    catch ( ... )
    {
        // Drop the incomplete group so the next write() can reuse its name.
        H5Ldelete( _file_id, g.c_str(), H5P_DEFAULT );
        H5Eclear2( H5E_DEFAULT );
        throw;
    }
    _records.push_back( std::move( record ) );
}

//---------------------------------------------------------------------------//
void SnapshotWriter::writeVertexIds( const long n_points )
{
    // /vertex_ids = 0..n_max-1, the Polyvertex connectivity of every grid;
    // replaced by a longer one when a snapshot has more points.
    if ( n_points <= _vertex_id_count )
        return;
    const Hdf5Check check{ _partial_path };
    if ( _vertex_id_count > 0 )
        check( H5Ldelete( _file_id, "/vertex_ids", H5P_DEFAULT ), "H5Ldelete",
               "/vertex_ids" );
    std::vector<int> ids( n_points );
    std::iota( ids.begin(), ids.end(), 0 );
    writeDataset( check, _file_id, "/vertex_ids", "vertex_ids", H5T_STD_I32LE,
                  H5T_NATIVE_INT, ids.size(), 1, ids.data(), "1" );
    _vertex_id_count = n_points;
}

//---------------------------------------------------------------------------//
void SnapshotWriter::finalize()
{
    if ( _finalized )
        return;
    _finalized = true;

    // Close the file, then publish it under its final name.
    {
        SilenceHdf5Errors silence;
        Hdf5Check{ _partial_path }( H5Fclose( _file_id ), "H5Fclose", "/" );
    }
    if ( std::rename( _partial_path.c_str(), _h5_path.c_str() ) != 0 )
    {
        const int error_number = errno;
        throw std::runtime_error(
            "mpm::SnapshotWriter::finalize: rename '" + _partial_path +
            "' -> '" + _h5_path +
            "' failed: " + std::strerror( error_number ) );
    }
    writeTextAtomically( _xdmf_path, buildXdmf() );
}

//---------------------------------------------------------------------------//
std::string SnapshotWriter::buildXdmf() const
{
    // Data items point into the final .h5, relative to the .xdmf folder.
    const std::string h5 = xmlEscape( _stem + ".h5" );
    std::string out = "<?xml version=\"1.0\" ?>\n"
                      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                      "<Xdmf Version=\"2.0\">\n  <Domain>\n    <Grid Name=\"" +
                      xmlEscape( _stem ) +
                      "\" GridType=\"Collection\" "
                      "CollectionType=\"Temporal\">\n";
    for ( std::size_t s = 0; s < _records.size(); ++s )
    {
        const SnapshotRecord& r = _records[s];
        const std::string name = snapshotName( s );
        const std::string n = std::to_string( r.n_points );

        // Geometry first, then one node-centred Attribute per other field.
        std::string fields;
        for ( const bool geometry : { true, false } )
            for ( const FieldRecord& f : r.fields )
            {
                if ( ( f.name == "x" ) != geometry )
                    continue;
                const std::string type = f.components == 1   ? "Scalar"
                                         : f.components <= 3 ? "Vector"
                                                             : "Matrix";
                fields += fill(
                    field_xdmf,
                    { { "element", geometry ? "Geometry" : "Attribute" },
                      { "kind", geometry ? "GeometryType=\"XY\""
                                         : "Name=\"" + xmlEscape( f.name ) +
                                               "\" AttributeType=\"" + type +
                                               "\" Center=\"Node\"" },
                      { "dims",
                        f.components == 1
                            ? n
                            : n + " " + std::to_string( f.components ) },
                      { "type", f.is_int ? "Int\" Precision=\"4"
                                         : "Float\" Precision=\"8" },
                      { "path", h5 + ":/snapshots/" + name + "/" +
                                    xmlEscape( f.name ) } } );
            }
        out +=
            fill( grid_xdmf, { { "name", name },
                               { "time", formatDouble( r.time_s ) },
                               { "stage", xmlEscape( r.stage ) },
                               { "n", n },
                               { "n_ids", std::to_string( _vertex_id_count ) },
                               { "h5", h5 },
                               { "fields", fields },
                               { "stage_time", formatDouble( r.stage_time_s ) },
                               { "step", std::to_string( r.step ) } } );
    }
    return out + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

} // namespace mpm
