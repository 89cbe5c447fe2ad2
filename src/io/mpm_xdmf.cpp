#include <io/mpm_xdmf.hpp>

#include <charconv>
#include <cstdio>
#include <map>
#include <string>

namespace mpm
{
namespace
{
std::string xmlEscape( const std::string& text )
{
    const std::string special = "&<>\"'";
    const char* const entities[] = { "&amp;", "&lt;", "&gt;", "&quot;",
                                     "&apos;" };
    std::string out;
    for ( const char c : text )
    {
        const auto k = special.find( c );
        out += k == std::string::npos ? std::string( 1, c ) : entities[k];
    }
    return out;
}

// Replaces each @key@ in `text` in one pass (values are not rescanned).
std::string fill( const std::string& text,
                  const std::map<std::string, std::string>& values )
{
    std::string out;
    std::size_t i = 0;
    for ( std::size_t at; ( at = text.find( '@', i ) ) != std::string::npos; )
    {
        const std::size_t end = text.find( '@', at + 1 );
        out += text.substr( i, at - i ) +
               values.at( text.substr( at + 1, end - at - 1 ) );
        i = end + 1;
    }
    return out + text.substr( i );
}

// XDMF text of one snapshot and of one node-centred attribute, for fill().
const char* const grid_xdmf =
    R"(      <Grid Name="snapshot_@name@" GridType="Uniform">
        <Time Value="@time@"/>
        <Information Name="stage" Value="@stage@"/>
        <Topology TopologyType="Polyvertex" NumberOfElements="@n@" NodesPerElement="1">
          <DataItem ItemType="HyperSlab" Dimensions="@n@" Type="HyperSlab">
            <DataItem Dimensions="3 1" Format="XML">0 1 @n@</DataItem>
            <DataItem Dimensions="@n_ids@" NumberType="Int" Precision="4" Format="HDF">@h5@:/vertex_ids</DataItem>
          </DataItem>
        </Topology>
        <Geometry GeometryType="XY">
          <DataItem Dimensions="@n@ 2" NumberType="Float" Precision="8" Format="HDF">@h5@:/snapshots/@name@/x</DataItem>
        </Geometry>
@attributes@        <Attribute Name="stage_time_s" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Float" Precision="8" Format="XML">@stage_time@</DataItem>
        </Attribute>
        <Attribute Name="step" AttributeType="Scalar" Center="Grid">
          <DataItem Dimensions="1" NumberType="Int" Precision="8" Format="XML">@step@</DataItem>
        </Attribute>
      </Grid>
)";
const char* const attribute_xdmf =
    R"(        <Attribute Name="@field@" AttributeType="@type@" Center="Node">
          <DataItem Dimensions="@dims@" NumberType="@number@" Format="HDF">@h5@:/snapshots/@name@/@field@</DataItem>
        </Attribute>
)";

} // namespace

//---------------------------------------------------------------------------//
std::string formatDouble( const double value )
{
    char buffer[64];
    return std::string( buffer,
                        std::to_chars( buffer, buffer + 64, value ).ptr );
}

//---------------------------------------------------------------------------//
std::string snapshotGroupName( const std::size_t index )
{
    char buffer[32];
    std::snprintf( buffer, sizeof( buffer ), "%06zu", index );
    return buffer;
}

//---------------------------------------------------------------------------//
std::string xdmfText( const std::string& stem,
                      const std::vector<XdmfSnapshot>& snapshots,
                      const long vertex_id_count )
{
    // Data items point into the final .h5, relative to the .xdmf folder.
    const std::string h5 = xmlEscape( stem + ".h5" );
    std::string out = "<?xml version=\"1.0\" ?>\n"
                      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                      "<Xdmf Version=\"2.0\">\n  <Domain>\n    <Grid Name=\"" +
                      xmlEscape( stem ) +
                      "\" GridType=\"Collection\" "
                      "CollectionType=\"Temporal\">\n";
    for ( std::size_t s = 0; s < snapshots.size(); ++s )
    {
        const XdmfSnapshot& r = snapshots[s];
        const std::string name = snapshotGroupName( s );
        const std::string n = std::to_string( r.n_points );

        // Every field except the positions "x" (the Geometry) is an Attribute.
        std::string attributes;
        for ( const XdmfField& f : r.fields )
            if ( f.name != "x" )
                attributes +=
                    fill( attribute_xdmf,
                          { { "field", xmlEscape( f.name ) },
                            { "type", f.components == 1   ? "Scalar"
                                      : f.components <= 3 ? "Vector"
                                                          : "Matrix" },
                            { "dims",
                              f.components == 1
                                  ? n
                                  : n + " " + std::to_string( f.components ) },
                            { "number", f.is_int ? "Int\" Precision=\"4"
                                                 : "Float\" Precision=\"8" },
                            { "h5", h5 },
                            { "name", name } } );
        out +=
            fill( grid_xdmf, { { "name", name },
                               { "time", formatDouble( r.time_s ) },
                               { "stage", xmlEscape( r.stage ) },
                               { "n", n },
                               { "n_ids", std::to_string( vertex_id_count ) },
                               { "h5", h5 },
                               { "attributes", attributes },
                               { "stage_time", formatDouble( r.stage_time_s ) },
                               { "step", std::to_string( r.step ) } } );
    }
    return out + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

} // namespace mpm
