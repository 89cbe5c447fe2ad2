#include <io/mpm_json_output.hpp>
#include <io/mpm_safe_file.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mpm
{
namespace
{
//---------------------------------------------------------------------------//
// Throws a runtime_error naming the path, the operation and errno's text.
[[noreturn]] void throwErrno( const std::string& path,
                              const std::string& operation,
                              const int error_number )
{
    throw std::runtime_error( "mpm::writeTextAtomically: " + operation +
                              " failed for '" + path +
                              "': " + std::strerror( error_number ) );
}

} // namespace

//---------------------------------------------------------------------------//
void writeTextAtomically( const std::string& path, const std::string& text )
{
    // The temporary file lives in the same folder so rename() stays atomic.
    const std::string tmp_path =
        path + ".tmp." + std::to_string( static_cast<long>( ::getpid() ) );

    // Created exclusively: a symlink planted at tmp_path is not followed.
    int fd = -1;
    try
    {
        fd = createExclusive( tmp_path );
    }
    catch ( const std::runtime_error& e )
    {
        throw std::runtime_error( std::string( "mpm::writeTextAtomically: " ) +
                                  e.what() + " (temporary file for '" + path +
                                  "')" );
    }

    // Write everything, retrying on short writes and EINTR.
    const char* data = text.data();
    std::size_t remaining = text.size();
    while ( remaining > 0 )
    {
        const ssize_t written = ::write( fd, data, remaining );
        if ( written < 0 )
        {
            if ( errno == EINTR )
                continue;
            const int error_number = errno;
            ::close( fd );
            std::remove( tmp_path.c_str() );
            throwErrno( tmp_path, "write", error_number );
        }
        data += written;
        remaining -= static_cast<std::size_t>( written );
    }

    // Make the content durable before it becomes visible under `path`.
    if ( ::fsync( fd ) != 0 )
    {
        const int error_number = errno;
        ::close( fd );
        std::remove( tmp_path.c_str() );
        throwErrno( tmp_path, "fsync", error_number );
    }
    if ( ::close( fd ) != 0 )
    {
        const int error_number = errno;
        std::remove( tmp_path.c_str() );
        throwErrno( tmp_path, "close", error_number );
    }

    // Atomic replace.
    if ( std::rename( tmp_path.c_str(), path.c_str() ) != 0 )
    {
        const int error_number = errno;
        std::remove( tmp_path.c_str() );
        throwErrno( path, "rename from '" + tmp_path + "'", error_number );
    }
}

//---------------------------------------------------------------------------//
void writeJsonAtomically( const std::string& path, const nlohmann::json& value )
{
    const std::string text =
        value.dump( 2, ' ', false, nlohmann::json::error_handler_t::replace ) +
        "\n";
    writeTextAtomically( path, text );
}

} // namespace mpm
