#include <io/mpm_case_file.hpp>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mpm
{
namespace Impl
{
namespace
{
//! What a file of this mode is, for "found ..." in messages.
std::string fileKind( const mode_t mode )
{
    if ( S_ISDIR( mode ) )
        return "a directory";
    if ( S_ISFIFO( mode ) )
        return "a FIFO (named pipe)";
    if ( S_ISCHR( mode ) )
        return "a character device";
    if ( S_ISBLK( mode ) )
        return "a block device";
    if ( S_ISSOCK( mode ) )
        return "a socket";
    return "not a regular file";
}

//! Closes a file descriptor on scope exit.
struct FileDescriptor
{
    int fd;
    ~FileDescriptor()
    {
        if ( fd >= 0 )
            ::close( fd );
    }
};

} // namespace

//---------------------------------------------------------------------------//
std::string readRegularFile( const std::string& path,
                             const std::size_t max_bytes )
{
    const std::string expected =
        "expected a readable regular file of at most " +
        std::to_string( max_bytes ) + " bytes, found ";
    // O_NONBLOCK: opening a FIFO without a writer must not wait for one.
    const FileDescriptor file{
        ::open( path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC ) };
    if ( file.fd < 0 )
        throw CaseFileError( expected + "a file that cannot be opened (" +
                             std::strerror( errno ) + ")" );
    struct stat info;
    if ( ::fstat( file.fd, &info ) != 0 )
        throw CaseFileError( expected + "a file that cannot be examined (" +
                             std::strerror( errno ) + ")" );
    if ( !S_ISREG( info.st_mode ) )
        throw CaseFileError( expected + fileKind( info.st_mode ) );
    if ( static_cast<unsigned long long>( info.st_size ) > max_bytes )
        throw CaseFileError( expected + "a file of " +
                             std::to_string( info.st_size ) + " bytes" );

    // Read at most max_bytes + 1 bytes (the file may grow meanwhile).
    std::string text( static_cast<std::size_t>( info.st_size ), '\0' );
    std::size_t length = 0;
    char extra = 0;
    for ( ;; )
    {
        char* buffer = length < text.size() ? &text[length] : &extra;
        const std::size_t wanted =
            length < text.size() ? text.size() - length : 1;
        const ssize_t got = ::read( file.fd, buffer, wanted );
        if ( got < 0 && errno == EINTR )
            continue;
        if ( got < 0 )
            throw CaseFileError( expected + "a file that cannot be read (" +
                                 std::strerror( errno ) + ")" );
        if ( got == 0 )
            break;
        if ( buffer == &extra )
        {
            if ( text.size() >= max_bytes )
                throw CaseFileError( expected +
                                     "a file that grows while it is read" );
            text.push_back( extra );
        }
        length += static_cast<std::size_t>( got );
    }
    text.resize( length );
    return text;
}

} // namespace Impl
} // namespace mpm
