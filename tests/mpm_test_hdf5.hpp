#ifndef MPM_TEST_HDF5_HPP
#define MPM_TEST_HDF5_HPP

// HDF5 helpers of the tests that read rainslide's output files.
#include <hdf5.h>

#include <cstdio>

#include <filesystem>
#include <string>
#include <vector>

namespace mpm_test
{
//! Number of snapshot groups in a particles.h5 file (-1 if unreadable).
inline int snapshotCount( const std::filesystem::path& h5 )
{
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    if ( file < 0 )
        return -1;
    const hid_t group = H5Gopen2( file, "/snapshots", H5P_DEFAULT );
    H5G_info_t info;
    const herr_t status = H5Gget_info( group, &info );
    H5Gclose( group );
    H5Fclose( file );
    return status < 0 ? -1 : static_cast<int>( info.nlinks );
}

//! Dataset `name` of the last snapshot of a particles.h5 file, as doubles
//! (empty if unreadable).
inline std::vector<double> lastSnapshotField( const std::filesystem::path& h5,
                                              const std::string& name )
{
    const int count = snapshotCount( h5 );
    if ( count <= 0 )
        return {};
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    char group[32];
    std::snprintf( group, sizeof group, "/snapshots/%06d/", count - 1 );
    const hid_t dset =
        H5Dopen2( file, ( std::string( group ) + name ).c_str(), H5P_DEFAULT );
    std::vector<double> data;
    if ( dset >= 0 )
    {
        const hid_t space = H5Dget_space( dset );
        data.resize(
            static_cast<std::size_t>( H5Sget_simple_extent_npoints( space ) ) );
        if ( H5Dread( dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                      data.data() ) < 0 )
            data.clear();
        H5Sclose( space );
        H5Dclose( dset );
    }
    H5Fclose( file );
    return data;
}

//! String attribute `name` of `object` in file `h5` ("" if unreadable).
inline std::string readStringAttribute( const std::filesystem::path& h5,
                                        const char* object, const char* name )
{
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    const hid_t attribute =
        H5Aopen_by_name( file, object, name, H5P_DEFAULT, H5P_DEFAULT );
    const hid_t type = H5Aget_type( attribute );
    std::string text( type < 0 ? 0 : H5Tget_size( type ), '\0' );
    if ( type < 0 || H5Tis_variable_str( type ) != 0 ||
         H5Aread( attribute, type, text.data() ) < 0 )
        text.clear();
    H5Tclose( type );
    H5Aclose( attribute );
    H5Fclose( file );
    return text.substr( 0, text.find( '\0' ) );
}

//! Replaces attribute `name` of `object` in file `h5` by the string
//! `text` (deleted and created again); false if that fails.
inline bool writeStringAttribute( const std::filesystem::path& h5,
                                  const char* object, const char* name,
                                  const std::string& text )
{
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT );
    const hid_t type = H5Tcopy( H5T_C_S1 );
    H5Tset_size( type, text.size() + 1 );
    H5Tset_cset( type, H5T_CSET_UTF8 );
    const hid_t space = H5Screate( H5S_SCALAR );
    bool ok = H5Adelete_by_name( file, object, name, H5P_DEFAULT ) >= 0;
    const hid_t attribute =
        H5Acreate_by_name( file, object, name, type, space, H5P_DEFAULT,
                           H5P_DEFAULT, H5P_DEFAULT );
    ok = ok && attribute >= 0 && H5Awrite( attribute, type, text.c_str() ) >= 0;
    H5Aclose( attribute );
    H5Sclose( space );
    H5Tclose( type );
    return H5Fclose( file ) >= 0 && ok;
}

} // namespace mpm_test

#endif // MPM_TEST_HDF5_HPP
