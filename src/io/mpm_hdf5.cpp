#include <io/mpm_hdf5.hpp>

#include <stdexcept>
#include <type_traits>

static_assert( std::is_same<hid_t, std::int64_t>::value,
               "rainslide stores hid_t as std::int64_t (HDF5 >= 1.10)" );

namespace mpm
{
namespace Impl
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

} // namespace

//---------------------------------------------------------------------------//
Hdf5Ops::Hdf5Ops( const std::string& who, const std::string& file )
    : _who( who )
    , _file( file )
    , _saved( H5Eget_auto2( H5E_DEFAULT, &_func, &_data ) >= 0 )
{
    H5Eset_auto2( H5E_DEFAULT, nullptr, nullptr );
}

Hdf5Ops::~Hdf5Ops()
{
    for ( auto it = _ids.rbegin(); it != _ids.rend(); ++it )
        it->closer( it->id );
    if ( _saved )
        H5Eset_auto2( H5E_DEFAULT, _func, _data );
}

void Hdf5Ops::fail( const char* operation, const std::string& object ) const
{
    throw std::runtime_error( _who + ": " + std::string( operation ) +
                              " failed for '" + object + "' in file '" + _file +
                              "'" + hdf5ErrorDetail() );
}

hid_t Hdf5Ops::open( const hid_t id, const char* operation,
                     herr_t ( *closer )( hid_t ), const std::string& object )
{
    _ids.push_back( { check( id, operation, object ), closer, object } );
    return id;
}

void Hdf5Ops::closeAll()
{
    while ( !_ids.empty() )
    {
        const OpenId last = _ids.back();
        _ids.pop_back();
        check( last.closer( last.id ), "close", last.object );
    }
}

//---------------------------------------------------------------------------//
void Hdf5Ops::writeAttribute( const hid_t loc, const std::string& object,
                              const char* name,
                              const AttributeValue& value ) const
{
    const std::string at = object + "@" + name;
    Hdf5Ops h5( _who, _file );
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

void Hdf5Ops::writeDataset( const hid_t group, const std::string& path,
                            const hid_t file_type, const hid_t mem_type,
                            const std::vector<hsize_t>& dims, const void* data,
                            const std::string& unit ) const
{
    Hdf5Ops h5( _who, _file );
    const hid_t space =
        h5.open( H5Screate_simple( static_cast<int>( dims.size() ), dims.data(),
                                   nullptr ),
                 "H5Screate_simple", H5Sclose, path );
    const hid_t dset =
        h5.open( H5Dcreate2( group, path.c_str(), file_type, space, H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT ),
                 "H5Dcreate2", H5Dclose, path );
    hsize_t count = 1;
    for ( const hsize_t d : dims )
        count *= d;
    if ( count > 0 )
        h5.check(
            H5Dwrite( dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data ),
            "H5Dwrite", path );
    if ( !unit.empty() )
        writeAttribute( dset, path, "unit", unit );
    h5.closeAll();
}

//---------------------------------------------------------------------------//
AttributeValue Hdf5Ops::readAttribute( const hid_t loc,
                                       const std::string& object,
                                       const char* name ) const
{
    const std::string at = object + "@" + name;
    Hdf5Ops h5( _who, _file );
    const hid_t attr =
        h5.open( H5Aopen( loc, name, H5P_DEFAULT ), "H5Aopen", H5Aclose, at );
    const hid_t type =
        h5.open( H5Aget_type( attr ), "H5Aget_type", H5Tclose, at );
    AttributeValue value;
    switch ( H5Tget_class( type ) )
    {
    case H5T_FLOAT:
    {
        double v = 0.0;
        h5.check( H5Aread( attr, H5T_NATIVE_DOUBLE, &v ), "H5Aread", at );
        value = v;
        break;
    }
    case H5T_INTEGER:
    {
        std::int64_t v = 0;
        h5.check( H5Aread( attr, H5T_NATIVE_INT64, &v ), "H5Aread", at );
        value = v;
        break;
    }
    case H5T_STRING:
    {
        if ( H5Tis_variable_str( type ) > 0 )
            fail( "reading a variable-length string", at );
        std::string text( H5Tget_size( type ), '\0' );
        h5.check( H5Aread( attr, type, text.data() ), "H5Aread", at );
        value = text.substr( 0, text.find( '\0' ) );
        break;
    }
    default:
        fail( "reading an attribute of unsupported type", at );
    }
    h5.closeAll();
    return value;
}

bool Hdf5Ops::hasAttribute( const hid_t loc, const std::string& object,
                            const char* name ) const
{
    return check( H5Aexists( loc, name ), "H5Aexists", object + "@" + name ) >
           0;
}

std::vector<hsize_t> Hdf5Ops::datasetDims( const hid_t loc,
                                           const std::string& path ) const
{
    Hdf5Ops h5( _who, _file );
    const hid_t dset = h5.open( H5Dopen2( loc, path.c_str(), H5P_DEFAULT ),
                                "H5Dopen2", H5Dclose, path );
    const hid_t space =
        h5.open( H5Dget_space( dset ), "H5Dget_space", H5Sclose, path );
    const int rank = h5.check( H5Sget_simple_extent_ndims( space ),
                               "H5Sget_simple_extent_ndims", path );
    std::vector<hsize_t> dims( rank );
    h5.check( H5Sget_simple_extent_dims( space, dims.data(), nullptr ),
              "H5Sget_simple_extent_dims", path );
    h5.closeAll();
    return dims;
}

void Hdf5Ops::readDataset( const hid_t loc, const std::string& path,
                           const hid_t mem_type, void* data ) const
{
    Hdf5Ops h5( _who, _file );
    const hid_t dset = h5.open( H5Dopen2( loc, path.c_str(), H5P_DEFAULT ),
                                "H5Dopen2", H5Dclose, path );
    const hid_t space =
        h5.open( H5Dget_space( dset ), "H5Dget_space", H5Sclose, path );
    if ( h5.check( H5Sget_simple_extent_npoints( space ),
                   "H5Sget_simple_extent_npoints", path ) > 0 )
        h5.check(
            H5Dread( dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data ),
            "H5Dread", path );
    h5.closeAll();
}

std::vector<std::string> Hdf5Ops::linkNames( const hid_t loc,
                                             const std::string& object,
                                             const bool creation_order ) const
{
    std::vector<std::string> names;
    const H5L_iterate_t collect = []( hid_t, const char* name,
                                      const H5L_info_t*, void* out ) -> herr_t
    {
        static_cast<std::vector<std::string>*>( out )->push_back( name );
        return 0;
    };
    if ( creation_order && H5Literate( loc, H5_INDEX_CRT_ORDER, H5_ITER_INC,
                                       nullptr, collect, &names ) >= 0 )
        return names;
    H5Eclear2( H5E_DEFAULT );
    names.clear();
    check(
        H5Literate( loc, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names ),
        "H5Literate", object );
    return names;
}

} // namespace Impl
} // namespace mpm
