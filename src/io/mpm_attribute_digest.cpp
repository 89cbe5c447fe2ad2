#include <io/mpm_attribute_digest.hpp>
#include <io/mpm_case_fingerprint.hpp>

#include <cstdio>
#include <cstring>

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
std::string AttributeDigest::hex() const
{
    std::string all;
    for ( const auto& [path, text] : _entries )
        all += std::to_string( path.size() ) + ":" + path + "=" + text + "\n";
    return hashText( fnv1aHash( all ) );
}

} // namespace Impl
} // namespace mpm
