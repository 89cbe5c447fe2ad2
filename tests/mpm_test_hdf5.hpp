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

} // namespace mpm_test

#endif // MPM_TEST_HDF5_HPP
