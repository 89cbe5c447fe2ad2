#ifndef MPM_TEST_HDF5_HPP
#define MPM_TEST_HDF5_HPP

// HDF5 helpers of the tests that read rainslide's output files.
#include <hdf5.h>

#include <filesystem>

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

} // namespace mpm_test

#endif // MPM_TEST_HDF5_HPP
