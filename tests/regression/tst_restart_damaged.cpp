// Restarts from damaged files (issue 12): a checkpoint with out-of-range
// indices or non-finite values, or a malformed probes.csv, is refused with
// exit 2 before anything is written (once a SIGSEGV in G2P, a run reading
// out of bounds to "completed", or particles.h5 cut to the kept snapshots).
#include <mpm_test_cli.hpp>
#include <mpm_test_hdf5.hpp>

#include <io/mpm_checkpoint.hpp>

#include <hdf5.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

namespace
{
namespace fs = std::filesystem;

using mpm_test::CommandResult;
using mpm_test::runCommand;

/*!
  A saturated column 0.5 m x 2 m with p_w held on its top points and rain
  on a polyline along its top, one dynamic stage: its checkpoint has point
  conditions (water/p_w_condition_p, water/inflow_p).
*/
const std::string two_phase_text = mpm_test::saturatedColumnCaseText(
    "wet_column",
    "\n" + mpm_test::stageToml( "rain", "dynamic", "0.2" ) +
        mpm_test::heldBoxToml( "[[0.0, 1.75], [0.5, 2.0]]", "0.0" ) +
        mpm_test::polylineInflowToml( "[[0.0, 2.0], [0.5, 2.0]]", "1.0e-4" ) );

//! A run of `text` (default: the test block) stopped after 30 steps
//! (checkpoint and probes in dir/out); returns the case file.
fs::path
stoppedRun( const fs::path& dir,
            const std::string& text = mpm_test::probedBlockCaseText( "0.2" ) )
{
    fs::remove_all( dir );
    fs::create_directories( dir );
    const fs::path file = mpm_test::writeCase( dir, text );
    const auto stopped = runCommand( mpm_test::runArgs(
        file, dir / "out", " --quiet --stop-after-steps 30" ) );
    EXPECT_EQ( stopped.exit_code, 130 ) << stopped.output;
    return file;
}

//! Flips the bits `mask` of the byte at `offset` of `file`.
void flipByte( const fs::path& file, const std::uintmax_t offset,
               const int mask )
{
    std::fstream f( file, std::ios::in | std::ios::out | std::ios::binary );
    f.seekg( static_cast<std::streamoff>( offset ) );
    char byte = 0;
    f.read( &byte, 1 );
    byte = static_cast<char>( byte ^ mask );
    f.seekp( static_cast<std::streamoff>( offset ) );
    f.write( &byte, 1 );
}

//! `run` of `file` restarted from `checkpoint` (Serial, quiet), then `extra`.
CommandResult restartRun( const fs::path& file, const fs::path& checkpoint,
                          const std::string& extra = "" )
{
    return runCommand( "run " + file.string() + " --backend serial --quiet" +
                       extra + " --restart " + checkpoint.string() );
}

//! Restart after `damage` changed the checkpoint: exit 2 with `fragment`.
void expectDamageRefused(
    const std::string& name,
    const std::function<void( mpm::Checkpoint& )>& damage,
    const std::string& fragment,
    const std::string& text = mpm_test::probedBlockCaseText( "0.2" ) )
{
    SCOPED_TRACE( name );
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / ( "rainslide_damaged_" + name );
    const fs::path file = stoppedRun( dir, text );
    const std::string checkpoint = ( dir / "out" / "checkpoint.h5" ).string();
    mpm::Checkpoint c = mpm::readCheckpoint( checkpoint );
    damage( c );
    mpm::writeCheckpoint( checkpoint, c );
    mpm_test::expectExit( restartRun( file, checkpoint ), 2,
                          "is damaged: " + fragment );
}

mpm::CheckpointArray& array( mpm::Checkpoint& c, const std::string& name )
{
    for ( auto& a : c.arrays )
        if ( a.name == name )
            return a;
    throw std::runtime_error( "no array " + name );
}

//! Restart after the index `array_name`[index] was set to `value`: refused
//! as outside `range`.
void expectIndexRefused(
    const std::string& name, const std::string& array_name, const int index,
    const int value, const std::string& range,
    const std::string& text = mpm_test::probedBlockCaseText( "0.2" ) )
{
    expectDamageRefused(
        name,
        [&]( mpm::Checkpoint& c )
        { array( c, array_name ).integers[index] = value; },
        array_name + "[" + std::to_string( index ) +
            "]: expected an index in " + range + ", found " +
            std::to_string( value ),
        text );
}

//---------------------------------------------------------------------------//
TEST( RestartDamaged, out_of_range_values_are_refused )
{
    expectIndexRefused( "material", "particles/material_p", 3, 7, "0..0" );
    expectDamageRefused(
        "position",
        []( mpm::Checkpoint& c )
        {
            array( c, "particles/x_p" ).reals[5] =
                std::numeric_limits<double>::quiet_NaN();
        },
        "particles/x_p[5]: expected a finite number" );
    expectDamageRefused(
        "time",
        []( mpm::Checkpoint& c )
        { c.time_s = std::numeric_limits<double>::quiet_NaN(); },
        "time_s: expected a finite time >= 0 s" );
    expectDamageRefused(
        "snapshots", []( mpm::Checkpoint& c ) { c.snapshots.count = -3; },
        "snapshot_count: expected >= 0, found -3" );
}

//---------------------------------------------------------------------------//
// The point conditions index the stage's lists (one pore-pressure
// condition, one inflow, no load): out of range they read out of bounds.
// The water fields are checked for finite values like the solid's (they
// were skipped: their group is "water/", not "water_particles/").
TEST( RestartDamaged, out_of_range_point_conditions_are_refused )
{
    expectIndexRefused( "condition", "water/p_w_condition_p", 2, 1, "-1..0",
                        two_phase_text );
    expectIndexRefused( "inflow", "water/inflow_p", 0, -2, "-1..0",
                        two_phase_text );
    expectIndexRefused( "load", "particles/load_p", 1, 0, "-1..-1",
                        two_phase_text );
    expectDamageRefused(
        "load_group",
        []( mpm::Checkpoint& c ) { c.load_groups.push_back( { 3 } ); },
        "conditions/load_group_members (group 0): expected load indices in "
        "0..-1, found 3",
        two_phase_text );
    expectDamageRefused(
        "water_pressure",
        []( mpm::Checkpoint& c )
        {
            array( c, "water/p_w_p" ).reals[4] =
                std::numeric_limits<double>::infinity();
        },
        "water/p_w_p[4]: expected a finite number", two_phase_text );
}

//---------------------------------------------------------------------------//
TEST( RestartDamaged, flipped_byte_in_a_dataset_is_refused )
{
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / "rainslide_damaged_flip";
    const fs::path file = stoppedRun( dir );
    const fs::path checkpoint = dir / "out" / "checkpoint.h5";
    // Where the positions' data lie in the file.
    haddr_t address = 0;
    {
        const hid_t h5 =
            H5Fopen( checkpoint.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT );
        ASSERT_GE( h5, 0 );
        const hid_t dset = H5Dopen2( h5, "/state/particles/x_p", H5P_DEFAULT );
        ASSERT_GE( dset, 0 );
        hsize_t offset[2];
        unsigned filter_mask = 0;
        hsize_t size = 0;
        const hid_t space = H5Dget_space( dset );
        const herr_t found = H5Dget_chunk_info( dset, space, 0, offset,
                                                &filter_mask, &address, &size );
        H5Sclose( space );
        ASSERT_GE( found, 0 ) << "x_p is not chunked";
        H5Dclose( dset );
        H5Fclose( h5 );
    }
    flipByte( checkpoint, address + 100, 0x10 );
    mpm_test::expectExit( restartRun( file, checkpoint ), 2,
                          "cannot read checkpoint" );
}

// An attribute changed in place (a valid, finite time) is caught by the
// attribute checksum: attributes carry no Fletcher-32 of their own.
TEST( RestartDamaged, changed_attribute_is_refused )
{
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / "rainslide_damaged_attribute";
    const fs::path file = stoppedRun( dir );
    const fs::path checkpoint = dir / "out" / "checkpoint.h5";
    for ( const char* object : { "/", "/loop" } )
    {
        SCOPED_TRACE( object );
        const std::string copy = checkpoint.string() + ".copy";
        fs::copy_file( checkpoint, copy, fs::copy_options::overwrite_existing );
        if ( std::string( object ) == "/loop" )
        {
            // The loop state's JSON text with another (finite) ke_max.
            auto loop = nlohmann::json::parse(
                mpm_test::readStringAttribute( copy, "/loop", "json" ) );
            loop["ke_max"] = loop["ke_max"].get<double>() * 0.5 + 1.0e-3;
            ASSERT_TRUE( mpm_test::writeStringAttribute( copy, "/loop", "json",
                                                         loop.dump() ) );
        }
        else
        {
            // Read, delete and write again (H5Awrite in place fails on
            // dense attribute storage in HDF5 1.10).
            const hid_t h5 = H5Fopen( copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT );
            ASSERT_GE( h5, 0 );
            const char* name = "time_s";
            double value = 0.0;
            const hid_t old =
                H5Aopen_by_name( h5, object, name, H5P_DEFAULT, H5P_DEFAULT );
            ASSERT_GE( old, 0 );
            ASSERT_GE( H5Aread( old, H5T_NATIVE_DOUBLE, &value ), 0 );
            H5Aclose( old );
            ASSERT_GE( H5Adelete_by_name( h5, object, name, H5P_DEFAULT ), 0 );
            value = value * 0.5 + 1.0e-3;
            const hid_t space = H5Screate( H5S_SCALAR );
            const hid_t attribute =
                H5Acreate_by_name( h5, object, name, H5T_IEEE_F64LE, space,
                                   H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT );
            ASSERT_GE( attribute, 0 );
            ASSERT_GE( H5Awrite( attribute, H5T_NATIVE_DOUBLE, &value ), 0 );
            H5Aclose( attribute );
            H5Sclose( space );
            H5Fclose( h5 );
        }
        mpm_test::expectExit(
            restartRun( file, copy, " --out " + ( dir / "again" ).string() ), 2,
            "do not match their checksum: the file is damaged" );
    }
}

// Random single-byte flips anywhere in a checkpoint (issue 12: 20 of 93
// restarted silently to other results): each restart is refused (exit 2)
// or ends as the undamaged restart does, bit for bit (Serial). Datasets
// carry Fletcher-32, attributes a digest, metadata HDF5's own checksums.
TEST( RestartDamaged, random_byte_flips_are_refused_or_harmless )
{
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / "rainslide_damaged_random";
    const fs::path file = stoppedRun( dir );
    const fs::path out = dir / "out";
    const fs::path checkpoint = out / "checkpoint.h5";
    const auto restart = [&]( const fs::path& from, const std::string& name )
    {
        fs::remove_all( dir / name );
        return restartRun( file, from, " --out " + ( dir / name ).string() );
    };
    const auto reference = restart( checkpoint, "reference" );
    ASSERT_EQ( reference.exit_code, 0 ) << reference.output;
    const auto final_x =
        mpm_test::lastSnapshotField( dir / "reference" / "particles.h5", "x" );
    const auto final_stress = mpm_test::lastSnapshotField(
        dir / "reference" / "particles.h5", "stress" );
    ASSERT_FALSE( final_x.empty() );

    const auto size = fs::file_size( checkpoint );
    std::uint64_t state = 12345; // a fixed LCG: the same flips every run
    int refused = 0, harmless = 0;
    for ( int k = 0; k < 150; ++k )
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::uintmax_t at = ( state >> 16 ) % size;
        const fs::path flipped = out / "flipped.h5";
        fs::copy_file( checkpoint, flipped,
                       fs::copy_options::overwrite_existing );
        flipByte( flipped, at, 1 << ( k % 8 ) );
        const auto result = restart( flipped, "flipped" );
        SCOPED_TRACE( "byte " + std::to_string( at ) + " of " +
                      std::to_string( size ) + ": exit " +
                      std::to_string( result.exit_code ) );
        if ( result.exit_code == 2 )
        {
            ++refused;
            continue;
        }
        ASSERT_EQ( result.exit_code, 0 ) << result.output;
        ++harmless;
        const fs::path h5 = dir / "flipped" / "particles.h5";
        EXPECT_EQ( mpm_test::lastSnapshotField( h5, "x" ), final_x );
        EXPECT_EQ( mpm_test::lastSnapshotField( h5, "stress" ), final_stress );
    }
    std::printf( "Random checkpoint byte flips: %d refused, %d restarted to "
                 "the undamaged result, of %ju bytes\n",
                 refused, harmless, static_cast<std::uintmax_t>( size ) );
}

TEST( RestartDamaged, malformed_probes_file_keeps_the_particles )
{
    const fs::path dir =
        fs::path( ::testing::TempDir() ) / "rainslide_damaged_probes";
    const fs::path file = stoppedRun( dir );
    const fs::path out = dir / "out";
    const fs::path h5 = fs::exists( out / "particles.h5" )
                            ? out / "particles.h5"
                            : out / "particles.h5.partial";
    const int before = mpm_test::snapshotCount( h5 );
    ASSERT_GT( before, 0 );
    const fs::path csv = fs::exists( out / "probes.csv" )
                             ? out / "probes.csv"
                             : out / "probes.csv.partial";
    std::ofstream( csv, std::ios::app ) << "garbage,load,top\n";
    mpm_test::expectExit( restartRun( file, out / "checkpoint.h5" ), 2,
                          "expected the time in s as the first column, found "
                          "'garbage'" );
    EXPECT_EQ( mpm_test::snapshotCount( h5 ), before );
}

} // namespace
