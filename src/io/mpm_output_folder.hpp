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

} // namespace mpm

#endif // MPM_OUTPUT_FOLDER_HPP
