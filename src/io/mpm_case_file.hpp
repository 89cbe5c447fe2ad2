#ifndef MPM_CASE_FILE_HPP
#define MPM_CASE_FILE_HPP

#include <cstddef>
#include <stdexcept>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
//! A case file that is not a readable regular file of bounded size.
class CaseFileError : public std::runtime_error
{
  public:
    explicit CaseFileError( const std::string& message )
        : std::runtime_error( message )
    {
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The contents of a regular file of at most max_bytes bytes.

  The file is opened without blocking (a FIFO does not hang) and checked
  to be a regular file before anything is read (a directory, a device such
  as /dev/zero, a FIFO or a socket is refused); at most max_bytes + 1
  bytes are read.

  \throw CaseFileError with a message "expected ..., found ..." (without
  the file name, which the caller adds).
*/
std::string readRegularFile( const std::string& path, std::size_t max_bytes );

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_FILE_HPP
