#ifndef MPM_OUTPUT_FOLDER_HPP
#define MPM_OUTPUT_FOLDER_HPP

#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Why out_dir must not receive a run's files, or "" if it may: the
  root folder, a system folder (/bin, /boot, /dev, /etc, /lib, /proc,
  /sbin, /sys, /usr, /var and folders inside /dev, /proc, /sys), the home
  folder itself, or a path that exists and is not a folder. Symlinks in
  the path are resolved first (a link to / is /).
*/
std::string unsafeOutputFolder( const std::string& out_dir );

//---------------------------------------------------------------------------//
/*!
  \brief Why out_dir must not receive the results of the case `case_file`
  (the run's files would lie among case files), or "" if it may: it is the
  case file's own folder, or it holds a case file (*.toml). Symlinks are
  resolved first.
*/
std::string caseFilesInOutputFolder( const std::string& out_dir,
                                     const std::string& case_file );

} // namespace mpm

#endif // MPM_OUTPUT_FOLDER_HPP
