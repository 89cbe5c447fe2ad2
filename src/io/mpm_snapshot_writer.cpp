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
#include <variant>

static_assert( std::is_same<hid_t, std::int64_t>::value,
               "SnapshotWriter stores hid_t as std::int64_t (HDF5 >= 1.10)" );

namespace mpm
{
namespace
{
//---------------------------------------------------------------------------//
// " (HDF5: <API-level message>; <innermost message>)", or "".
std::string hdf5ErrorDetail()
{
    std::vector<std::string> msgs;
    const H5E_walk2_t collect = []( unsigned, const H5E_error2_t* err,
                                    void* out ) -> herr_t
    {
        if ( err != nullptr && err->desc != nullptr )
            static_cast<std::vector<std::string>*>( out )->push_back(
                err->desc );
        return 0;
    };
    if ( H5Ewalk2( H5E_DEFAULT, H5E_WALK_UPWARD, collect, &msgs ) < 0 ||
         msgs.empty() )
        return "";
    H5Eclear2( H5E_DEFAULT );
    return " (HDF5: " + msgs.back() +
           ( msgs.size() > 1 ? "; " + msgs.front() : "" ) + ")";
}

//---------------------------------------------------------------------------//
// Checked HDF5 calls on one file, with HDF5's own error printing off for
// the object's lifetime. check() throws a runtime_error naming the file, the
// object and the operation; open() checks and keeps an id that closeAll()
// closes (checked) and the destructor (error path) closes quietly.
class Hdf5Ops
{
  public:
    explicit Hdf5Ops( const std::string& file )
        : _file( file )
        , _saved( H5Eget_auto2( H5E_DEFAULT, &_func, &_data ) >= 0 )
    {
        H5Eset_auto2( H5E_DEFAULT, nullptr, nullptr );
    }
    ~Hdf5Ops()
    {
        for ( auto it = _ids.rbegin(); it != _ids.rend(); ++it )
            it->closer( it->id );
        if ( _saved )
            H5Eset_auto2( H5E_DEFAULT, _func, _data );
    }
    template <class T>
    T check( const T status, const char* operation,
             const std::string& object ) const
    {
        if ( status < 0 )
            throw std::runtime_error(
                "mpm::SnapshotWriter: " + std::string( operation ) +
                " failed for '" + object + "' in file '" + _file + "'" +
                hdf5ErrorDetail() );
        return status;
    }
    hid_t open( const hid_t id, const char* operation,
                herr_t ( *closer )( hid_t ), const std::string& object )
    {
        _ids.push_back( { check( id, operation, object ), closer, object } );
        return id;
    }
    void closeAll()
    {
        while ( !_ids.empty() )
        {
            const OpenId last = _ids.back();
            _ids.pop_back();
            check( last.closer( last.id ), "close", last.object );
        }
    }

  private:
    struct OpenId
    {
        hid_t id;
        herr_t ( *closer )( hid_t );
        std::string object;
    };
    std::string _file;
    std::vector<OpenId> _ids;
    H5E_auto2_t _func = nullptr;
    void* _data = nullptr;
    bool _saved;
};

//---------------------------------------------------------------------------//
// Scalar attribute `name` on `loc` (`object` is its path, for messages);
// strings are fixed-length, null-terminated UTF-8.
using AttributeValue = std::variant<double, std::int64_t, std::string>;
void writeAttribute( const std::string& file, const hid_t loc,
                     const std::string& object, const char* name,
                     const AttributeValue& value )
{
    const std::string at = object + "@" + name;
    Hdf5Ops h5( file );
    hid_t type = value.index() == 0 ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
    const void* data =
        std::visit( []( const auto& v ) -> const void* { return &v; }, value );
    if ( const auto* text = std::get_if<std::string>( &value ) )
    {
        // H5T_C_S1 is null-terminated; size it and mark it UTF-8.
        type = h5.open( H5Tcopy( H5T_C_S1 ), "H5Tcopy", H5Tclose, at );
        h5.check( H5Tset_size( type, text->size() + 1 ), "H5Tset_size", at );
        h5.check( H5Tset_cset( type, H5T_CSET_UTF8 ), "H5Tset_cset", at );
        data = text->c_str();
    }
    const hid_t space =
        h5.open( H5Screate( H5S_SCALAR ), "H5Screate", H5Sclose, at );
    const hid_t attr =
        h5.open( H5Acreate2( loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT ),
                 "H5Acreate2", H5Aclose, at );
    h5.check( H5Awrite( attr, type, data ), "H5Awrite", at );
    h5.closeAll();
}

// Dataset [n] (1 component) or [n x components] with a "unit" attribute.
void writeDataset( const std::string& file, const hid_t group,
                   const std::string& path, const hid_t file_type,
                   const hid_t mem_type, const hsize_t n, const int components,
                   const void* data, const std::string& unit )
{
    Hdf5Ops h5( file );
    const hsize_t dims[2] = { n, static_cast<hsize_t>( components ) };
    const hid_t space =
        h5.open( H5Screate_simple( components == 1 ? 1 : 2, dims, nullptr ),
                 "H5Screate_simple", H5Sclose, path );
    const hid_t dset =
        h5.open( H5Dcreate2( group, path.c_str(), file_type, space, H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT ),
                 "H5Dcreate2", H5Dclose, path );
    if ( n > 0 )
        h5.check(
            H5Dwrite( dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data ),
            "H5Dwrite", path );
    writeAttribute( file, dset, path, "unit", unit );
    h5.closeAll();
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

// Shortest decimal text that reads back as the same double.
std::string formatDouble( const double value )
{
    char buffer[64];
    return std::string( buffer,
                        std::to_chars( buffer, buffer + 64, value ).ptr );
}

std::string snapshotName( const std::size_t index )
{
    char buffer[32];
    std::snprintf( buffer, sizeof( buffer ), "%06zu", index );
    return buffer;
}

// XDMF text of one snapshot and of one node-centred attribute, for fill().
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
        <Geometry GeometryType="XY">
          <DataItem Dimensions="@n@ 2" NumberType="Float" Precision="8" Format="HDF">@h5@:/snapshots/@name@/x</DataItem>
        </Geometry>
@attributes@        <Attribute Name="stage_time_s" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Float" Precision="8" Format="XML">@stage_time@</DataItem>
        </Attribute>
        <Attribute Name="step" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Int" Precision="8" Format="XML">@step@</DataItem>
        </Attribute>
      </Grid>
)";
const char* const attribute_xdmf =
    R"(        <Attribute Name="@field@" AttributeType="@type@" Center="Node">
          <DataItem Dimensions="@dims@" NumberType="@number@" Format="HDF">@h5@:/snapshots/@name@/@field@</DataItem>
        </Attribute>
)";

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
    Hdf5Ops h5( _partial_path );
    _file_id = h5.check( H5Fcreate( _partial_path.c_str(), H5F_ACC_TRUNC,
                                    H5P_DEFAULT, H5P_DEFAULT ),
                         "H5Fcreate", "/" );
    try
    {
        writeAttribute( _partial_path, _file_id, "/", "format",
                        std::string( "rainslide-particles-1" ) );
        writeAttribute( _partial_path, _file_id, "/", "snapshot_count",
                        std::int64_t( 0 ) );
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

    Hdf5Ops h5( _partial_path );
    const std::string& file = _partial_path;
    const std::string g = "/snapshots/" + snapshotName( _records.size() );
    const auto n = static_cast<hsize_t>( n_points );
    try
    {
        // Group, its attributes and one dataset per field.
        const hid_t group =
            h5.open( H5Gcreate2( _file_id, g.c_str(), H5P_DEFAULT, H5P_DEFAULT,
                                 H5P_DEFAULT ),
                     "H5Gcreate2", H5Gclose, g );
        writeAttribute( file, group, g, "time_s", time_s );
        writeAttribute( file, group, g, "stage", stage );
        writeAttribute( file, group, g, "stage_time_s", stage_time_s );
        writeAttribute( file, group, g, "step", std::int64_t( step ) );
        writeAttribute( file, group, g, "n_points", std::int64_t( n_points ) );
        for ( const auto& f : fields )
            writeDataset( file, group, g + "/" + f.name, H5T_IEEE_F64LE,
                          H5T_NATIVE_DOUBLE, n, f.components, f.data, f.unit );
        for ( const auto& f : int_fields )
            writeDataset( file, group, g + "/" + f.name, H5T_STD_I32LE,
                          H5T_NATIVE_INT, n, 1, f.data, "1" );
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
        // Drop the incomplete group so the next write() can reuse its name.
        H5Ldelete( _file_id, g.c_str(), H5P_DEFAULT );
        H5Eclear2( H5E_DEFAULT );
        throw;
    }
    SnapshotRecord record{ time_s, stage, stage_time_s, step, n_points, {} };
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
        Hdf5Ops( _partial_path )
            .check( H5Ldelete( _file_id, "/vertex_ids", H5P_DEFAULT ),
                    "H5Ldelete", "/vertex_ids" );
    _vertex_id_count = 0;
    std::vector<int> ids( n_points );
    std::iota( ids.begin(), ids.end(), 0 );
    writeDataset( _partial_path, _file_id, "/vertex_ids", H5T_STD_I32LE,
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
    Hdf5Ops( _partial_path ).check( H5Fclose( _file_id ), "H5Fclose", "/" );
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

        // Every field except the positions "x" (the Geometry) is an Attribute.
        std::string attributes;
        for ( const FieldRecord& f : r.fields )
            if ( f.name != "x" )
                attributes +=
                    fill( attribute_xdmf,
                          { { "field", xmlEscape( f.name ) },
                            { "type", f.components == 1   ? "Scalar"
                                      : f.components <= 3 ? "Vector"
                                                          : "Matrix" },
                            { "dims",
                              f.components == 1
                                  ? n
                                  : n + " " + std::to_string( f.components ) },
                            { "number", f.is_int ? "Int\" Precision=\"4"
                                                 : "Float\" Precision=\"8" },
                            { "h5", h5 },
                            { "name", name } } );
        out +=
            fill( grid_xdmf, { { "name", name },
                               { "time", formatDouble( r.time_s ) },
                               { "stage", xmlEscape( r.stage ) },
                               { "n", n },
                               { "n_ids", std::to_string( _vertex_id_count ) },
                               { "h5", h5 },
                               { "attributes", attributes },
                               { "stage_time", formatDouble( r.stage_time_s ) },
                               { "step", std::to_string( r.step ) } } );
    }
    return out + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

} // namespace mpm
