#ifndef MPM_HDF5_HPP
#define MPM_HDF5_HPP

// Checked HDF5 helpers shared by the snapshot writer and the checkpoint
// files (internal to src/io: include only from .cpp files).

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace mpm
{
namespace Impl
{
//! A scalar attribute: double, 64-bit integer or UTF-8 string.
using AttributeValue = std::variant<double, std::int64_t, std::string>;

//---------------------------------------------------------------------------//
/*!
  \brief Checked HDF5 calls on one file, with HDF5's own error printing off
  for the object's lifetime.

  check() throws a std::runtime_error "<who>: <operation> failed for
  '<object>' in file '<file>' (HDF5: ...)"; open() checks and keeps an id
  that closeAll() closes (checked) and the destructor (error path) closes
  quietly. The read/write helpers use their own Hdf5Ops for their
  temporary ids, so nothing leaks when they throw.
*/
class Hdf5Ops
{
  public:
    Hdf5Ops( const std::string& who, const std::string& file );
    ~Hdf5Ops();
    Hdf5Ops( const Hdf5Ops& ) = delete;
    Hdf5Ops& operator=( const Hdf5Ops& ) = delete;

    template <class T>
    T check( const T status, const char* operation,
             const std::string& object ) const
    {
        if ( status < 0 )
            fail( operation, object );
        return status;
    }

    hid_t open( hid_t id, const char* operation, herr_t ( *closer )( hid_t ),
                const std::string& object );
    void closeAll();

    //! Scalar attribute `name` on `loc` (`object` is its path, for
    //! messages); strings are fixed-length, null-terminated UTF-8.
    void writeAttribute( hid_t loc, const std::string& object, const char* name,
                         const AttributeValue& value ) const;

    //! Dataset `path` in `group` with the given extents (rank = dims.size(),
    //! 1 for a plain array) and, unless `unit` is empty, a "unit" attribute.
    void writeDataset( hid_t group, const std::string& path, hid_t file_type,
                       hid_t mem_type, const std::vector<hsize_t>& dims,
                       const void* data, const std::string& unit ) const;

    //! A scalar attribute: float classes read as double, integer classes
    //! as int64, strings as std::string.
    AttributeValue readAttribute( hid_t loc, const std::string& object,
                                  const char* name ) const;

    //! True if `loc` has an attribute `name`.
    bool hasAttribute( hid_t loc, const std::string& object,
                       const char* name ) const;

    //! Extents of dataset `path` in `loc`.
    std::vector<hsize_t> datasetDims( hid_t loc,
                                      const std::string& path ) const;

    //! Reads all of dataset `path` into `data` (sized by the caller from
    //! datasetDims) as `mem_type`.
    void readDataset( hid_t loc, const std::string& path, hid_t mem_type,
                      void* data ) const;

    //! Names of the links in group `loc` (at path `object`): in creation
    //! order if `creation_order` and the group tracks it, else in name order.
    std::vector<std::string> linkNames( hid_t loc, const std::string& object,
                                        bool creation_order = false ) const;

    const std::string& file() const { return _file; }

  private:
    [[noreturn]] void fail( const char* operation,
                            const std::string& object ) const;

    struct OpenId
    {
        hid_t id;
        herr_t ( *closer )( hid_t );
        std::string object;
    };
    std::string _who;
    std::string _file;
    std::vector<OpenId> _ids;
    H5E_auto2_t _func = nullptr;
    void* _data = nullptr;
    bool _saved;
};

} // namespace Impl
} // namespace mpm

#endif // MPM_HDF5_HPP
