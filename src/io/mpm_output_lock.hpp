#ifndef MPM_OUTPUT_LOCK_HPP
#define MPM_OUTPUT_LOCK_HPP

#include <stdexcept>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
//! An output folder that cannot take a run's files: not writable, or in
//! use by another run (the message names the folder and says which).
class OutputFolderError : public std::runtime_error
{
  public:
    explicit OutputFolderError( const std::string& message )
        : std::runtime_error( message )
    {
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief The exclusive use of an output folder by one run: the folder is
  created if missing, and the file `<folder>/.rainslide.lock` holds the
  run's process id under an flock(2) lock, which the system releases when
  the process ends however it ends (a killed run leaves no lock behind, at
  most the file, which the next run takes over). The destructor removes the
  file, releases the lock and removes the folder again if it created it and
  it is still empty (a refused run leaves no trace).
*/
class OutputLock
{
  public:
    //! Name of the lock file in the output folder.
    static constexpr const char* file_name = ".rainslide.lock";

    /*!
      \throw OutputFolderError if the folder cannot be created or written
      ("the output folder 'X' is not writable (Read-only file system)"), or
      another process holds its lock (naming its process id).
    */
    explicit OutputLock( const std::string& out_dir );
    ~OutputLock();
    OutputLock( const OutputLock& ) = delete;
    OutputLock& operator=( const OutputLock& ) = delete;

  private:
    std::string _folder;
    std::string _path;
    int _fd = -1;
    bool _created = false; //!< the folder did not exist before
};

} // namespace mpm

#endif // MPM_OUTPUT_LOCK_HPP
