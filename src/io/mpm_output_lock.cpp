#include <io/mpm_output_lock.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mpm
{
namespace
{
std::string notWritable( const std::string& folder, const std::string& why )
{
    return "the output folder '" + folder + "' is not writable (" + why +
           "); choose another folder with --out";
}

//! The first line of the lock file open as fd (the holder's process id).
std::string holder( const int fd )
{
    char buf[64] = {};
    const ssize_t n = ::pread( fd, buf, sizeof buf - 1, 0 );
    std::string text( buf, n > 0 ? static_cast<std::size_t>( n ) : 0 );
    text = text.substr( 0, text.find( '\n' ) );
    return text.empty() ? "unknown" : text;
}

//! True if fd and path are the same file (the lock file was not removed
//! and created again between open and flock).
bool sameFile( const int fd, const std::string& path )
{
    struct stat open_file = {}, named = {};
    return ::fstat( fd, &open_file ) == 0 &&
           ::stat( path.c_str(), &named ) == 0 &&
           open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

} // namespace

//---------------------------------------------------------------------------//
OutputLock::OutputLock( const std::string& out_dir )
{
    namespace fs = std::filesystem;
    std::error_code ec;
    _folder = out_dir;
    _created = !fs::exists( out_dir, ec );
    fs::create_directories( out_dir, ec );
    if ( ec )
        throw OutputFolderError( notWritable( out_dir, ec.message() ) );
    if ( ::access( out_dir.c_str(), W_OK | X_OK ) != 0 )
        throw OutputFolderError(
            notWritable( out_dir, std::strerror( errno ) ) );
    _path = ( fs::path( out_dir ) / file_name ).string();
    for ( int attempt = 0; attempt < 100; ++attempt )
    {
        const int fd = ::open(
            _path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644 );
        if ( fd < 0 )
            throw OutputFolderError(
                notWritable( out_dir, std::strerror( errno ) ) );
        if ( ::flock( fd, LOCK_EX | LOCK_NB ) != 0 )
        {
            const int error_number = errno;
            const std::string pid = holder( fd );
            ::close( fd );
            if ( error_number != EWOULDBLOCK )
                throw OutputFolderError(
                    "cannot lock the output folder '" + out_dir +
                    "': " + std::strerror( error_number ) );
            throw OutputFolderError(
                "the output folder '" + out_dir +
                "' is in use by another rainslide run (process " + pid +
                ", lock file " + _path +
                "); wait for it to end or choose another folder with --out" );
        }
        if ( !sameFile( fd, _path ) )
        {
            ::close( fd ); // its holder removed it: take the new one
            continue;
        }
        const std::string pid = std::to_string( ::getpid() ) + "\n";
        if ( ::ftruncate( fd, 0 ) != 0 ||
             ::pwrite( fd, pid.data(), pid.size(), 0 ) !=
                 static_cast<ssize_t>( pid.size() ) )
        {
            const int error_number = errno;
            ::close( fd );
            throw OutputFolderError(
                notWritable( out_dir, std::strerror( error_number ) ) );
        }
        _fd = fd;
        return;
    }
    throw OutputFolderError( "cannot lock the output folder '" + out_dir +
                             "': its lock file keeps changing" );
}

OutputLock::~OutputLock()
{
    if ( _fd < 0 )
        return;
    // Removed while held: a run that opened it before then sees another
    // file at the path once it gets the lock, and takes that one.
    ::unlink( _path.c_str() );
    ::close( _fd );
    if ( _created )
        ::rmdir( _folder.c_str() ); // only if empty
}

} // namespace mpm
