#include <io/mpm_attribute_digest.hpp>
#include <io/mpm_case_fingerprint.hpp>

#include <cstdint>
#include <cstring>
#include <string>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
void AttributeDigest::add( const std::string& path,
                           const AttributeValue& value )
{
    std::string text;
    if ( const auto* real = std::get_if<double>( &value ) )
    {
        std::uint64_t bits = 0;
        std::memcpy( &bits, real, sizeof bits );
        text = "d" + std::to_string( bits );
    }
    else if ( const auto* integer = std::get_if<std::int64_t>( &value ) )
        text = "i" + std::to_string( *integer );
    else
    {
        const std::string& s = std::get<std::string>( value );
        text = "s" + std::to_string( s.size() ) + ":" + s;
    }
    _entries[path] = text;
}

//---------------------------------------------------------------------------//
namespace
{
// The path of attribute `name` of the object at path `object`.
std::string attributePath( const std::string& object, const std::string& name )
{
    return object == "/" ? "/" + name : object + "/" + name;
}
} // namespace

void AttributeDigest::write( const Hdf5Ops& h5, const hid_t loc,
                             const std::string& object, const std::string& name,
                             const AttributeValue& value )
{
    h5.writeAttribute( loc, object, name.c_str(), value );
    add( attributePath( object, name ), value );
}

AttributeValue AttributeDigest::read( const Hdf5Ops& h5, const hid_t loc,
                                      const std::string& object,
                                      const std::string& name )
{
    AttributeValue value = h5.readAttribute( loc, object, name.c_str() );
    add( attributePath( object, name ), value );
    return value;
}

//---------------------------------------------------------------------------//
std::string AttributeDigest::hex() const
{
    std::string all;
    for ( const auto& [path, text] : _entries )
        all += std::to_string( path.size() ) + ":" + path + "=" + text + "\n";
    return hashText( fnv1aHash( all ) );
}

} // namespace Impl
} // namespace mpm
