#ifndef MPM_SAFE_FILE_HPP
#define MPM_SAFE_FILE_HPP

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Remove what is at path before a file is created there: a file or
  a symlink (the link itself, never its target); nothing if there is
  nothing or a folder (creating the file there then fails). Creating the new
  file with O_CREAT | O_EXCL (HDF5's H5F_ACC_EXCL) then never follows a symlink
  planted at path.

  \throw std::runtime_error if what is at path cannot be removed.
*/
void removeStale( const std::string& path );

//---------------------------------------------------------------------------//
/*!
  \brief Create a new file for writing: removeStale(path), then
  open(O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW). Returns the descriptor.

  \throw std::runtime_error naming the path and the reason.
*/
int createExclusive( const std::string& path );

//---------------------------------------------------------------------------//
//! Writes all of `text` to the descriptor fd (retrying short writes and
//! interruptions); false on an error (e.g. the disk is full).
bool writeAll( int fd, const std::string& text );

} // namespace mpm

#endif // MPM_SAFE_FILE_HPP
