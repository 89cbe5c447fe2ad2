// Restart through the CLI: `run --stop-after-steps` stops like Ctrl-C and
// `run --restart` continues to the outputs of an uninterrupted run; a
// changed case or missing snapshots are refused.
#include <mpm_test_cli.hpp>
#include <mpm_test_restart.hpp>

#include <hdf5.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace
{
namespace fs = std::filesystem;

using namespace mpm_test::restart;

//---------------------------------------------------------------------------//
// The CLI: `run --stop-after-steps` stops like Ctrl-C (checkpoint, exit
// 130, how to resume); `run --restart` continues; the particle file, its
// XDMF and the metrics equal those of an uninterrupted run.
using mpm_test::CommandResult;

CommandResult runCommand( const std::string& args )
{
    return mpm_test::runRainslide( args, scratch() / "cli.log" );
}

std::string readText( const fs::path& file )
{
    std::ifstream in( file );
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

//! Every snapshot of a particle file: "<group>@<attr>" and "<dataset>"
//! -> raw bytes.
std::map<std::string, std::string> snapshotBytes( const fs::path& h5 )
{
    std::map<std::string, std::string> out;
    const hid_t file = H5Fopen( h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
    if ( file < 0 )
        return out;
    struct Visit
    {
        hid_t file;
        std::map<std::string, std::string>* out;
    } visit{ file, &out };
    const H5O_iterate_t collect = []( hid_t, const char* name,
                                      const H5O_info_t* info,
                                      void* data ) -> herr_t
    {
        auto& v = *static_cast<Visit*>( data );
        const std::string path = std::string( "/snapshots/" ) + name;
        if ( info->type == H5O_TYPE_DATASET )
        {
            const hid_t dset = H5Dopen2( v.file, path.c_str(), H5P_DEFAULT );
            const hid_t type = H5Dget_type( dset );
            const hid_t space = H5Dget_space( dset );
            std::string bytes( H5Sget_simple_extent_npoints( space ) *
                                   H5Tget_size( type ),
                               '\0' );
            if ( !bytes.empty() )
                H5Dread( dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         bytes.data() );
            ( *v.out )[path] = bytes;
            H5Sclose( space );
            H5Tclose( type );
            H5Dclose( dset );
        }
        else if ( info->type == H5O_TYPE_GROUP )
            for ( const char* attr :
                  { "time_s", "stage", "stage_time_s", "step", "n_points" } )
            {
                if ( H5Aexists_by_name( v.file, path.c_str(), attr,
                                        H5P_DEFAULT ) <= 0 )
                    continue;
                const hid_t a = H5Aopen_by_name( v.file, path.c_str(), attr,
                                                 H5P_DEFAULT, H5P_DEFAULT );
                const hid_t type = H5Aget_type( a );
                std::string bytes( H5Tget_size( type ), '\0' );
                H5Aread( a, type, bytes.data() );
                ( *v.out )[path + "@" + attr] = bytes;
                H5Tclose( type );
                H5Aclose( a );
            }
        return 0;
    };
    const hid_t group = H5Gopen2( file, "/snapshots", H5P_DEFAULT );
    H5Ovisit( group, H5_INDEX_NAME, H5_ITER_INC, collect, &visit );
    H5Gclose( group );
    H5Fclose( file );
    return out;
}

void expectSameOutputs( const fs::path& full, const fs::path& resumed )
{
    const auto a = snapshotBytes( full / "particles.h5" );
    const auto b = snapshotBytes( resumed / "particles.h5" );
    EXPECT_GT( a.size(), 50u );
    EXPECT_EQ( a.size(), b.size() );
    for ( const auto& [key, bytes] : a )
    {
        const auto it = b.find( key );
        ASSERT_NE( it, b.end() ) << key;
        EXPECT_TRUE( it->second == bytes ) << key;
    }
    EXPECT_EQ( readText( full / "particles.xdmf" ),
               readText( resumed / "particles.xdmf" ) );
    EXPECT_FALSE( fs::exists( resumed / "particles.h5.partial" ) );
    const auto m_full =
        nlohmann::json::parse( readText( full / "metrics.json" ) );
    const auto m =
        nlohmann::json::parse( readText( resumed / "metrics.json" ) );
    for ( const char* key : { "status", "steps", "simulated_time_s", "stages",
                              "deformation", "dt_s", "dt_min_s" } )
        EXPECT_EQ( m_full[key], m[key] ) << key;
    EXPECT_EQ( m_full["output"]["snapshots"], m["output"]["snapshots"] );
    EXPECT_TRUE( m.contains( "restart" ) );
    EXPECT_GT( m["wall_s"].get<double>(),
               m["restart"]["wall_s_this_session"].get<double>() );
}

TEST( RestartCli, stop_and_restart_give_the_uninterrupted_outputs )
{
    const fs::path dir = freshDir( "cli" );
    const fs::path case_file = dir / "block.toml";
    std::ofstream( case_file ) << blockCase( "checkpoint_interval_s = 0.03" );
    const std::string run =
        "run " + case_file.string() + " --backend serial --quiet --out ";

    ASSERT_EQ( runCommand( run + ( dir / "full" ).string() ).exit_code, 0 );

    // Stopped in the first stage: exit 130, a checkpoint, how to go on.
    const fs::path part = dir / "part";
    auto stopped = runCommand( run + part.string() + " --stop-after-steps 30" );
    EXPECT_EQ( stopped.exit_code, 130 ) << stopped.output;
    EXPECT_NE( stopped.output.find( "checkpoint at step 30" ),
               std::string::npos )
        << stopped.output;
    EXPECT_NE( stopped.output.find( "--restart " +
                                    ( part / "checkpoint.h5" ).string() ),
               std::string::npos )
        << stopped.output;
    EXPECT_EQ(
        nlohmann::json::parse( readText( part / "metrics.json" ) )["status"],
        "interrupted" );
    const fs::path copy = dir / "copy";
    fs::copy( part, copy );

    // Continued in place (--out defaults to the checkpoint's folder).
    auto resumed = runCommand( "run " + case_file.string() +
                               " --backend serial --quiet --restart " +
                               ( part / "checkpoint.h5" ).string() );
    ASSERT_EQ( resumed.exit_code, 0 ) << resumed.output;
    expectSameOutputs( dir / "full", part );

    // Continued into another folder, after a "crash" that left the
    // particle file as .partial (with a snapshot after the checkpoint).
    fs::rename( copy / "particles.h5", copy / "particles.h5.partial" );
    resumed = runCommand( "run " + case_file.string() +
                          " --backend serial --quiet --restart " +
                          ( copy / "checkpoint.h5" ).string() + " --out " +
                          ( dir / "elsewhere" ).string() );
    ASSERT_EQ( resumed.exit_code, 0 ) << resumed.output;
    expectSameOutputs( dir / "full", dir / "elsewhere" );
}

TEST( RestartCli, changed_case_or_missing_snapshots_are_refused )
{
    const fs::path dir = freshDir( "cli_refused" );
    const fs::path case_file = dir / "block.toml";
    std::ofstream( case_file ) << blockCase( "" );
    const fs::path part = dir / "part";
    ASSERT_EQ( runCommand( "run " + case_file.string() +
                           " --backend serial --quiet --stop-after-steps 20 "
                           "--out " +
                           part.string() )
                   .exit_code,
               130 );
    const std::string before = readText( part / "metrics.json" );

    const fs::path changed = dir / "changed.toml";
    std::ofstream( changed ) << blockCase( "", 0.3 );
    auto result =
        runCommand( "run " + changed.string() + " --backend serial --restart " +
                    ( part / "checkpoint.h5" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE(
        result.output.find( "stages[0].duration_s: 0.2 in the checkpoint, 0.3 "
                            "now" ),
        std::string::npos )
        << result.output;
    EXPECT_EQ( readText( part / "metrics.json" ), before );

    fs::remove( part / "particles.h5" );
    result = runCommand( "run " + case_file.string() +
                         " --backend serial --restart " +
                         ( part / "checkpoint.h5" ).string() );
    EXPECT_EQ( result.exit_code, 2 ) << result.output;
    EXPECT_NE( result.output.find( "particles.h5: does not exist" ),
               std::string::npos )
        << result.output;
}

} // namespace
