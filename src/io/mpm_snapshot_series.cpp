// SnapshotWriter::findSeries: which file continues an interrupted run's
// snapshot series (restart).
#include <io/mpm_hdf5.hpp>
#include <io/mpm_snapshot_writer.hpp>
#include <io/mpm_xdmf.hpp>

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
std::string
SnapshotWriter::findSeries( const std::vector<std::string>& candidates,
                            const SnapshotSeriesMark& keep )
{
    if ( keep.count <= 0 )
        return "";
    const std::string last =
        "/snapshots/" + snapshotGroupName( keep.count - 1 );
    std::string reasons;
    for ( const std::string& path : candidates )
    {
        std::string reason;
        if ( !std::filesystem::exists( path ) )
            reason = "does not exist";
        else
            try
            {
                Impl::Hdf5Ops h5( "mpm::SnapshotWriter", path );
                const hid_t file = h5.open(
                    H5Fopen( path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT ),
                    "H5Fopen", H5Fclose, "/" );
                const auto complete = std::get<std::int64_t>(
                    h5.readAttribute( file, "/", "snapshot_count" ) );
                if ( complete < keep.count )
                    reason = "holds " + std::to_string( complete ) +
                             " complete snapshot(s), fewer than " +
                             std::to_string( keep.count );
                else
                {
                    const hid_t group =
                        h5.open( H5Gopen2( file, last.c_str(), H5P_DEFAULT ),
                                 "H5Gopen2", H5Gclose, last );
                    const auto step = std::get<std::int64_t>(
                        h5.readAttribute( group, last, "step" ) );
                    const double time_s = std::get<double>(
                        h5.readAttribute( group, last, "time_s" ) );
                    if ( step != keep.last_step || time_s != keep.last_time_s )
                        reason = "its snapshot " + last + " is step " +
                                 std::to_string( step ) +
                                 " at t = " + formatDouble( time_s ) +
                                 " s (another run of the case?)";
                }
                h5.closeAll();
            }
            catch ( const std::exception& e )
            {
                reason = e.what();
            }
        if ( reason.empty() )
            return path;
        reasons += "\n  " + path + ": " + reason;
    }
    throw std::runtime_error(
        "no snapshot file holds the " + std::to_string( keep.count ) +
        " snapshot(s) written before the checkpoint (the last at step " +
        std::to_string( keep.last_step ) +
        ", t = " + formatDouble( keep.last_time_s ) + " s):" + reasons );
}

} // namespace mpm
