#ifndef MPM_ATTRIBUTE_DIGEST_HPP
#define MPM_ATTRIBUTE_DIGEST_HPP

#include <io/mpm_hdf5.hpp>

#include <map>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief A checksum over HDF5 attributes (the checkpoint's scalar state:
  time, step, the stage loop): each attribute's path and exact value
  (doubles as their bits), hashed in path order, so the writer and the
  reader may visit them in any order. The datasets carry HDF5's
  Fletcher-32; this covers what attributes cannot. The checkpoint writes
  and reads its attributes through write() and read(), so none escapes.
*/
class AttributeDigest
{
  public:
    //! Takes in the attribute at `path` (e.g. "/loop/stage").
    void add( const std::string& path, const AttributeValue& value );
    //! Writes attribute `name` of `loc` (at path `object`) and takes it in.
    void write( const Hdf5Ops& h5, hid_t loc, const std::string& object,
                const std::string& name, const AttributeValue& value );
    //! Reads attribute `name` of `loc` (at path `object`) and takes it in.
    AttributeValue read( const Hdf5Ops& h5, hid_t loc,
                         const std::string& object, const std::string& name );
    //! The digest of everything taken in, 16 hex digits.
    std::string hex() const;

  private:
    std::map<std::string, std::string> _entries;
};

} // namespace Impl
} // namespace mpm

#endif // MPM_ATTRIBUTE_DIGEST_HPP
