#include <io/mpm_safe_file.hpp>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mpm
{
//---------------------------------------------------------------------------//
void removeStale( const std::string& path )
{
    struct stat info;
    if ( ::lstat( path.c_str(), &info ) != 0 )
    {
        if ( errno == ENOENT )
            return;
        throw std::runtime_error( "cannot examine '" + path +
                                  "': " + std::strerror( errno ) );
    }
    if ( S_ISDIR( info.st_mode ) )
        return; // creating the file then fails, naming it
    if ( ::unlink( path.c_str() ) != 0 && errno != ENOENT )
        throw std::runtime_error( "cannot remove the old '" + path +
                                  "': " + std::strerror( errno ) );
}

//---------------------------------------------------------------------------//
int createExclusive( const std::string& path )
{
    removeStale( path );
    const int fd = ::open( path.c_str(),
                           O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                           S_IRUSR | S_IWUSR | S_IRGRP | S_IROTH );
    if ( fd < 0 )
        throw std::runtime_error( "cannot create '" + path +
                                  "': " + std::strerror( errno ) );
    return fd;
}

//---------------------------------------------------------------------------//
bool writeAll( const int fd, const std::string& text )
{
    const char* data = text.data();
    std::size_t left = text.size();
    while ( left > 0 )
    {
        const ssize_t written = ::write( fd, data, left );
        if ( written < 0 && errno == EINTR )
            continue;
        if ( written <= 0 )
            return false;
        data += written;
        left -= static_cast<std::size_t>( written );
    }
    return true;
}

} // namespace mpm
