#ifndef MPM_TEST_XML_HPP
#define MPM_TEST_XML_HPP

// A minimal XML reader for the tests of the XDMF output
// (tst_snapshot_writer.cpp).
#include <cstddef>
#include <cstring>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mpm_test
{
// Minimal XML tree, enough to check well-formedness and read the XDMF.
struct XmlNode
{
    std::string tag;
    std::map<std::string, std::string> attrs;
    std::string text;
    std::vector<XmlNode> children;
};

inline std::string xmlUnescape( std::string t )
{
    const char* const entities[][2] = { { "&lt;", "<" },
                                        { "&gt;", ">" },
                                        { "&quot;", "\"" },
                                        { "&apos;", "'" },
                                        { "&amp;", "&" } };
    for ( const auto& e : entities )
        for ( auto p = t.find( e[0] ); p != t.npos; p = t.find( e[0], p + 1 ) )
            t.replace( p, std::strlen( e[0] ), e[1] );
    return t;
}

// Tokenizes tags with a regex and matches them on a stack; throws unless
// `text` is a single well-formed element (after an optional prolog).
inline XmlNode parseXml( const std::string& text )
{
    static const std::regex tag(
        R"re(<\?[^>]*\?>|<!DOCTYPE[^>]*>|<!--[\s\S]*?-->|)re"
        R"re(<(/?)([A-Za-z_][\w:.-]*)((?:\s+[\w:.-]+="[^"<]*")*)\s*(/?)>)re" );
    static const std::regex attribute( R"re(([\w:.-]+)="([^"]*)")re" );
    std::vector<XmlNode> stack( 1 ); // stack[0] holds the root when done
    std::size_t pos = 0;
    for ( std::sregex_iterator it( text.begin(), text.end(), tag ), end;
          it != end; ++it )
    {
        const std::smatch& m = *it;
        const std::string between = text.substr( pos, m.position() - pos );
        if ( between.find( '<' ) != std::string::npos )
            throw std::runtime_error( "XML: malformed markup: " + between );
        stack.back().text += between;
        pos = m.position() + m.length();
        if ( m[2].length() == 0 ) // prolog or comment
            continue;
        if ( m[1] == "/" )
        {
            if ( stack.size() < 2 || stack.back().tag != m[2] )
                throw std::runtime_error( "XML: unexpected </" + m[2].str() +
                                          ">" );
            XmlNode done = std::move( stack.back() );
            stack.pop_back();
            done.text = xmlUnescape( done.text );
            stack.back().children.push_back( std::move( done ) );
            continue;
        }
        XmlNode node{ m[2], {}, "", {} };
        const std::string attrs = m[3];
        for ( std::sregex_iterator a( attrs.begin(), attrs.end(), attribute );
              a != end; ++a )
            node.attrs[( *a )[1]] = xmlUnescape( ( *a )[2] );
        if ( m[4] == "/" )
            stack.back().children.push_back( node );
        else
            stack.push_back( node );
    }
    const bool blank =
        ( stack[0].text + text.substr( pos ) ).find_first_not_of( " \t\r\n" ) ==
        std::string::npos;
    if ( stack.size() != 1 || stack[0].children.size() != 1 || !blank )
        throw std::runtime_error( "XML: not one well-formed root element" );
    return stack[0].children[0];
}

} // namespace mpm_test

#endif // MPM_TEST_XML_HPP
