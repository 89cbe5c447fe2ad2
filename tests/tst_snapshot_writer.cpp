// The particle file writer: HDF5 round trip and XDMF, the partial file
// after a kill, finalization, errors naming the path, output safety.
#include <io/mpm_snapshot_writer.hpp>
#include <mpm_test_temp_dir.hpp>
#include <mpm_test_xml.hpp>

#include <gtest/gtest.h>
#include <hdf5.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

using mpm_test::listDir;
using mpm_test::parseXml;
using mpm_test::TempDir;
using mpm_test::XmlNode;

//---------------------------------------------------------------------------//
// HDF5 read helpers. Reads a whole dataset, its shape and its file type.
template <class T>
std::vector<T> readDataset( hid_t file, const std::string& path, hid_t mem_type,
                            hid_t file_type, std::vector<hsize_t> dims )
{
    const hid_t dset = H5Dopen2( file, path.c_str(), H5P_DEFAULT );
    EXPECT_GE( dset, 0 ) << path;
    const hid_t type = H5Dget_type( dset );
    const hid_t space = H5Dget_space( dset );
    EXPECT_GT( H5Tequal( type, file_type ), 0 ) << path;
    std::vector<hsize_t> actual( H5Sget_simple_extent_ndims( space ), 0 );
    H5Sget_simple_extent_dims( space, actual.data(), nullptr );
    EXPECT_EQ( actual, dims ) << path;
    std::vector<T> values( H5Sget_simple_extent_npoints( space ) );
    EXPECT_GE(
        H5Dread( dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data() ),
        0 );
    H5Sclose( space );
    H5Tclose( type );
    H5Dclose( dset );
    return values;
}

std::vector<double> readDoubles( hid_t file, const std::string& path,
                                 std::vector<hsize_t> dims )
{
    return readDataset<double>( file, path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
                                dims );
}

std::vector<int> readInts( hid_t file, const std::string& path, hsize_t n )
{
    return readDataset<int>( file, path, H5T_NATIVE_INT, H5T_STD_I32LE, { n } );
}

template <class T>
T readAttr( hid_t file, const std::string& object, const char* name,
            hid_t mem_type )
{
    T value{};
    const hid_t attr =
        H5Aopen_by_name( file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT );
    EXPECT_GE( attr, 0 ) << object << "@" << name;
    EXPECT_GE( H5Aread( attr, mem_type, &value ), 0 );
    H5Aclose( attr );
    return value;
}

std::string readStringAttr( hid_t file, const std::string& object,
                            const char* name )
{
    const hid_t attr =
        H5Aopen_by_name( file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT );
    EXPECT_GE( attr, 0 ) << object << "@" << name;
    const hid_t type = H5Aget_type( attr );
    std::string value( H5Tget_size( type ), '\0' );
    EXPECT_GE( H5Aread( attr, type, value.data() ), 0 );
    H5Tclose( type );
    H5Aclose( attr );
    return value.substr( 0, value.find( '\0' ) );
}

// Field values that differ per snapshot k and are not round numbers.
struct Fields
{
    static constexpr int n = 5;
    std::vector<double> x, sigma, p_w;
    std::vector<int> material;
    explicit Fields( const int k )
    {
        for ( int p = 0; p < n; ++p )
        {
            x.insert( x.end(), { 0.1 * p + k, -0.3 * p / 7.0 } );
            for ( int c = 0; c < 4; ++c )
                sigma.push_back( -1.0e5 / ( p + 1 ) + c * 1.0e3 / 3.0 + k );
            p_w.push_back( 9810.0 * p / 3.0 + k );
            material.push_back( 100 * k + p );
        }
    }
    void write( mpm::SnapshotWriter& w, double t, const std::string& stage,
                double stage_t, long step ) const
    {
        w.write( t, stage, stage_t, step, n,
                 { { "x", x.data(), 2, "m" },
                   { "sigma", sigma.data(), 4, "Pa" },
                   { "p_w", p_w.data(), 1, "Pa" } },
                 { { "material_id", material.data() } } );
    }
};

// Checks one snapshot group against Fields(k).
void expectSnapshot( hid_t file, const int k, const double t,
                     const std::string& stage, const double stage_t,
                     const long step )
{
    const Fields f( k );
    char name[32];
    std::snprintf( name, sizeof( name ), "/snapshots/%06d", k );
    const std::string g = name;
    EXPECT_EQ( readAttr<double>( file, g, "time_s", H5T_NATIVE_DOUBLE ), t );
    EXPECT_EQ( readStringAttr( file, g, "stage" ), stage );
    EXPECT_EQ( readAttr<double>( file, g, "stage_time_s", H5T_NATIVE_DOUBLE ),
               stage_t );
    EXPECT_EQ( readAttr<long long>( file, g, "step", H5T_NATIVE_LLONG ), step );
    EXPECT_EQ( readDoubles( file, g + "/x", { 5, 2 } ), f.x );
    EXPECT_EQ( readDoubles( file, g + "/sigma", { 5, 4 } ), f.sigma );
    EXPECT_EQ( readDoubles( file, g + "/p_w", { 5 } ), f.p_w );
    EXPECT_EQ( readInts( file, g + "/material_id", 5 ), f.material );
    EXPECT_EQ( readStringAttr( file, g + "/x", "unit" ), "m" );
    EXPECT_EQ( readStringAttr( file, g + "/sigma", "unit" ), "Pa" );
    EXPECT_EQ( readStringAttr( file, g + "/material_id", "unit" ), "1" );
}

} // namespace

//---------------------------------------------------------------------------//
TEST( SnapshotWriter, two_snapshots_round_trip_and_xdmf )
{
    TempDir tmp;
    const fs::path out = tmp.path / "run";
    mpm::SnapshotWriter writer( out.string() );
    Fields( 0 ).write( writer, 0.25, "gravity", 0.25, 10 );
    Fields( 1 ).write( writer, 1.0 / 3.0, "rain & <fall>", 0.1, 20 );
    EXPECT_EQ( writer.snapshotCount(), 2 );

    // Running: only the flushed .partial exists, and it is readable.
    EXPECT_EQ( listDir( out ),
               std::vector<std::string>{ "particles.h5.partial" } );
    {
        const hid_t file = H5Fopen( ( out / "particles.h5.partial" ).c_str(),
                                    H5F_ACC_RDONLY, H5P_DEFAULT );
        ASSERT_GE( file, 0 );
        EXPECT_EQ( readAttr<long long>( file, "/", "snapshot_count",
                                        H5T_NATIVE_LLONG ),
                   2 );
        expectSnapshot( file, 1, 1.0 / 3.0, "rain & <fall>", 0.1, 20 );
        EXPECT_GE( H5Fclose( file ), 0 );
    }

    writer.finalize();
    writer.finalize(); // idempotent
    EXPECT_EQ( writer.h5Path(), ( out / "particles.h5" ).string() );
    EXPECT_TRUE( fs::exists( writer.h5Path() ) );
    EXPECT_TRUE( fs::exists( writer.xdmfPath() ) );
    EXPECT_FALSE( fs::exists( out / "particles.h5.partial" ) );
    EXPECT_EQ( listDir( out ).size(), 2u ); // no temporary files left
    EXPECT_THROW( Fields( 2 ).write( writer, 2.0, "x", 0.0, 30 ),
                  std::logic_error );

    // Every dataset and attribute reads back exactly.
    const hid_t file =
        H5Fopen( writer.h5Path().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    ASSERT_GE( file, 0 );
    EXPECT_EQ( readStringAttr( file, "/", "format" ), "rainslide-particles-1" );
    expectSnapshot( file, 0, 0.25, "gravity", 0.25, 10 );
    expectSnapshot( file, 1, 1.0 / 3.0, "rain & <fall>", 0.1, 20 );
    EXPECT_EQ( readInts( file, "/vertex_ids", 5 ),
               ( std::vector<int>{ 0, 1, 2, 3, 4 } ) );
    EXPECT_GE( H5Fclose( file ), 0 );

    // The XDMF is well-formed and describes both snapshots.
    std::ifstream in( writer.xdmfPath() );
    std::stringstream text;
    text << in.rdbuf();
    XmlNode root;
    ASSERT_NO_THROW( root = parseXml( text.str() ) );
    EXPECT_THROW( parseXml( "<a><b></a>" ), std::runtime_error );
    EXPECT_THROW( parseXml( "<a x=\"1></a>" ), std::runtime_error );
    ASSERT_EQ( root.tag, "Xdmf" );
    const XmlNode& series = root.children.at( 0 ).children.at( 0 );
    EXPECT_EQ( series.attrs.at( "CollectionType" ), "Temporal" );
    ASSERT_EQ( series.children.size(), 2u );
    const double times[2] = { 0.25, 1.0 / 3.0 };
    for ( int k = 0; k < 2; ++k )
    {
        const std::string prefix =
            "particles.h5:/snapshots/00000" + std::to_string( k ) + "/";
        std::map<std::string, const XmlNode*> by_tag;
        std::map<std::string, const XmlNode*> attributes;
        for ( const XmlNode& c : series.children[k].children )
            ( c.tag == "Attribute" ? attributes[c.attrs.at( "Name" )]
                                   : by_tag[c.tag] ) = &c;
        EXPECT_EQ( std::stod( by_tag.at( "Time" )->attrs.at( "Value" ) ),
                   times[k] );
        EXPECT_EQ( by_tag.at( "Topology" )->attrs.at( "TopologyType" ),
                   "Polyvertex" );
        EXPECT_EQ( by_tag.at( "Geometry" )->attrs.at( "GeometryType" ), "XY" );
        EXPECT_EQ( by_tag.at( "Geometry" )->children.at( 0 ).text,
                   prefix + "x" );
        const XmlNode* sigma = attributes.at( "sigma" );
        EXPECT_EQ( sigma->attrs.at( "AttributeType" ), "Matrix" );
        EXPECT_EQ( sigma->children.at( 0 ).attrs.at( "Dimensions" ), "5 4" );
        EXPECT_EQ( sigma->children.at( 0 ).text, prefix + "sigma" );
        EXPECT_EQ( attributes.at( "p_w" )->attrs.at( "AttributeType" ),
                   "Scalar" );
        EXPECT_EQ( attributes.at( "material_id" )->children.at( 0 ).text,
                   prefix + "material_id" );
        EXPECT_EQ( attributes.count( "x" ), 0u );
    }
    EXPECT_EQ( series.children[1].children.at( 1 ).attrs.at( "Value" ),
               "rain & <fall>" );
}

//---------------------------------------------------------------------------//
TEST( SnapshotWriter, partial_file_is_readable_after_kill )
{
    TempDir tmp;
    const pid_t child = ::fork();
    ASSERT_GE( child, 0 );
    if ( child == 0 )
    {
        // Child: two snapshots, then die without any cleanup.
        try
        {
            mpm::SnapshotWriter writer( tmp.path.string() );
            Fields( 0 ).write( writer, 0.25, "gravity", 0.25, 10 );
            Fields( 1 ).write( writer, 0.5, "rain", 0.1, 20 );
            std::raise( SIGKILL );
        }
        catch ( ... )
        {
        }
        ::_exit( 3 );
    }
    int status = 0;
    ASSERT_EQ( ::waitpid( child, &status, 0 ), child );
    ASSERT_TRUE( WIFSIGNALED( status ) && WTERMSIG( status ) == SIGKILL );

    EXPECT_EQ( listDir( tmp.path ),
               std::vector<std::string>{ "particles.h5.partial" } );
    const hid_t file = H5Fopen( ( tmp.path / "particles.h5.partial" ).c_str(),
                                H5F_ACC_RDONLY, H5P_DEFAULT );
    ASSERT_GE( file, 0 );
    EXPECT_EQ(
        readAttr<long long>( file, "/", "snapshot_count", H5T_NATIVE_LLONG ),
        2 );
    expectSnapshot( file, 0, 0.25, "gravity", 0.25, 10 );
    expectSnapshot( file, 1, 0.5, "rain", 0.1, 20 );
    EXPECT_GE( H5Fclose( file ), 0 );
}

//---------------------------------------------------------------------------//
TEST( SnapshotWriter, destructor_finalizes )
{
    TempDir tmp;
    {
        mpm::SnapshotWriter writer( tmp.path.string(), "run1" );
        Fields( 0 ).write( writer, 0.0, "gravity", 0.0, 0 );
    }
    EXPECT_TRUE( fs::exists( tmp.path / "run1.h5" ) );
    EXPECT_TRUE( fs::exists( tmp.path / "run1.xdmf" ) );
    EXPECT_FALSE( fs::exists( tmp.path / "run1.h5.partial" ) );
}

//---------------------------------------------------------------------------//
TEST( SnapshotWriter, errors_name_the_path )
{
    TempDir tmp;
    // A regular file where a folder is needed.
    std::ofstream( tmp.path / "blocker" ) << "x";
    const std::string bad_dir = ( tmp.path / "blocker" / "out" ).string();
    try
    {
        mpm::SnapshotWriter writer( bad_dir );
        FAIL() << "expected an exception";
    }
    catch ( const std::runtime_error& e )
    {
        EXPECT_NE( std::string( e.what() ).find( bad_dir ), std::string::npos )
            << e.what();
    }

    // HDF5 cannot create the file: a folder sits at its path.
    fs::create_directories( tmp.path / "out" / "particles.h5.partial" );
    try
    {
        mpm::SnapshotWriter writer( ( tmp.path / "out" ).string() );
        FAIL() << "expected an exception";
    }
    catch ( const std::runtime_error& e )
    {
        const std::string what = e.what();
        EXPECT_NE( what.find( "particles.h5.partial" ), std::string::npos )
            << what;
        EXPECT_NE( what.find( "H5Fcreate" ), std::string::npos ) << what;
    }

    // Positions are required.
    mpm::SnapshotWriter writer( ( tmp.path / "ok" ).string() );
    const double p_w[2] = { 1.0, 2.0 };
    EXPECT_THROW(
        writer.write( 0.0, "s", 0.0, 0, 2, { { "p_w", p_w, 1, "Pa" } }, {} ),
        std::invalid_argument );
    EXPECT_EQ( writer.snapshotCount(), 0 );
}

//---------------------------------------------------------------------------//
// Output safety (issue 12): a symlink planted at a temporary name is
// removed, never followed; a failed write (disk full) is never published.
//---------------------------------------------------------------------------//
TEST( SnapshotWriter, symlink_at_partial_is_not_followed )
{
    TempDir tmp;
    const fs::path target = tmp.path / "precious.txt";
    std::ofstream( target ) << "precious";
    const fs::path out = tmp.path / "out";
    fs::create_directories( out );
    fs::create_symlink( target, out / "particles.h5.partial" );
    {
        mpm::SnapshotWriter writer( out.string() );
        Fields( 0 ).write( writer, 0.0, "gravity", 0.0, 0 );
    }
    std::ifstream in( target );
    std::string text;
    std::getline( in, text );
    EXPECT_EQ( text, "precious" );
    EXPECT_FALSE( fs::is_symlink( out / "particles.h5" ) );
    EXPECT_TRUE( fs::is_regular_file( out / "particles.h5" ) );
}

TEST( SnapshotWriter, failed_write_is_never_published )
{
    TempDir tmp;
    const fs::path out = tmp.path / "out";
    {
        mpm::SnapshotWriter writer( out.string() );
        Fields( 0 ).write( writer, 0.0, "gravity", 0.0, 0 );
    }
    const auto complete_size = fs::file_size( out / "particles.h5" );

    // A second run in the same folder on a "full disk": files may not grow
    // past 64 KiB (RLIMIT_FSIZE; SIGXFSZ ignored so write() fails).
    std::vector<double> big_x( 2 * 100000, 1.0 );
    auto* old_handler = std::signal( SIGXFSZ, SIG_IGN );
    rlimit old_limit;
    ::getrlimit( RLIMIT_FSIZE, &old_limit );
    rlimit limit = old_limit;
    limit.rlim_cur = 64 * 1024;
    ASSERT_EQ( ::setrlimit( RLIMIT_FSIZE, &limit ), 0 );
    bool threw = false, finalize_threw = false;
    {
        mpm::SnapshotWriter writer( out.string() );
        try
        {
            writer.write( 0.0, "gravity", 0.0, 0, 100000,
                          { { "x", big_x.data(), 2, "m" } }, {} );
        }
        catch ( const std::exception& )
        {
            threw = true;
        }
        try
        {
            writer.finalize();
        }
        catch ( const std::runtime_error& e )
        {
            finalize_threw = true;
            EXPECT_NE( std::string( e.what() ).find( "was not renamed" ),
                       std::string::npos )
                << e.what();
        }
    }
    ::setrlimit( RLIMIT_FSIZE, &old_limit );
    std::signal( SIGXFSZ, old_handler );
    EXPECT_TRUE( threw );
    EXPECT_TRUE( finalize_threw );
    // The complete file of the first run is kept.
    EXPECT_EQ( fs::file_size( out / "particles.h5" ), complete_size );
    const hid_t file = H5Fopen( ( out / "particles.h5" ).c_str(),
                                H5F_ACC_RDONLY, H5P_DEFAULT );
    ASSERT_GE( file, 0 );
    EXPECT_EQ(
        readAttr<long long>( file, "/", "snapshot_count", H5T_NATIVE_LLONG ),
        1 );
    H5Fclose( file );
}
