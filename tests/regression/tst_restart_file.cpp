// The checkpoint file: the loop state round-trips, an old or damaged one is
// refused, a failed write keeps the previous checkpoint, a checkpoint of a
// changed case file is refused.
#include <mpm_test_hdf5.hpp>
#include <mpm_test_loop_state.hpp>
#include <mpm_test_restart.hpp>

#include <io/mpm_case_fingerprint.hpp>
#include <io/mpm_case_reader.hpp>
#include <io/mpm_checkpoint.hpp>
#include <io/mpm_stage_state_json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace
{
namespace fs = std::filesystem;

using namespace mpm_test::restart;

//---------------------------------------------------------------------------//
// Every field of the loop state survives the file bit for bit (its JSON
// text, exact, compared), with many finished stages too.
TEST( RestartFile, loop_state_round_trips )
{
    const mpm::StageLoopState state = mpm_test::filledLoopState();
    mpm::Checkpoint checkpoint;
    checkpoint.loop = state;
    checkpoint.identity.case_fingerprint = "a = 1\n";
    checkpoint.load_groups = { { 0, 2 }, { 1 } };
    checkpoint.load_counts = { 3, 4, 5 };
    checkpoint.snapshots = { 7, 123, 0.25 };
    const fs::path file = freshDir( "round_trip" ) / "checkpoint.h5";
    mpm::writeCheckpoint( file.string(), checkpoint );
    const mpm::Checkpoint read = mpm::readCheckpoint( file.string() );
    EXPECT_EQ( mpm::stageLoopStateJson( read.loop ),
               mpm::stageLoopStateJson( state ) );
    EXPECT_EQ( mpm_test::readStringAttribute( file, "/loop", "json" ),
               mpm::stageLoopStateJson( state ) );
    EXPECT_TRUE( std::isnan( read.loop.stage_summary.ke_ratio ) );
    EXPECT_EQ( read.load_groups, checkpoint.load_groups );
    EXPECT_EQ( read.load_counts, checkpoint.load_counts );
    EXPECT_EQ( read.identity.case_fingerprint, "a = 1\n" );
    EXPECT_EQ( read.snapshots.count, 7 );
    EXPECT_EQ( read.snapshots.last_step, 123 );

    // 2000 finished stages: an attribute far above HDF5's 64 KiB compact
    // limit.
    checkpoint.loop.run.stages.assign( 2000, state.run.stages[0] );
    mpm::writeCheckpoint( file.string(), checkpoint );
    EXPECT_GT( mpm::stageLoopStateJson( checkpoint.loop ).size(), 500000u );
    EXPECT_EQ(
        mpm::stageLoopStateJson( mpm::readCheckpoint( file.string() ).loop ),
        mpm::stageLoopStateJson( checkpoint.loop ) );
}

// A checkpoint of format 1 (the loop state as one attribute per field) is
// refused by its format; a changed loop state by the checksum, one that
// is not JSON naming the file.
TEST( RestartFile, old_format_or_bad_loop_state_is_refused )
{
    const fs::path dir = freshDir( "old_format" );
    const fs::path file = dir / "checkpoint.h5";
    mpm::Checkpoint checkpoint;
    checkpoint.loop = mpm_test::filledLoopState();
    mpm::writeCheckpoint( file.string(), checkpoint );
    const std::string text =
        mpm_test::readStringAttribute( file, "/loop", "json" );
    ASSERT_FALSE( text.empty() );
    // Expects reading a copy of the file with attribute `name` of `object`
    // set to `value` to fail with a message holding `what` and its name.
    const auto expectRefused = [&]( const char* object, const char* name,
                                    const std::string& value,
                                    const std::string& what )
    {
        const fs::path damaged = dir / "damaged.h5";
        fs::copy_file( file, damaged, fs::copy_options::overwrite_existing );
        ASSERT_TRUE(
            mpm_test::writeStringAttribute( damaged, object, name, value ) );
        try
        {
            mpm::readCheckpoint( damaged.string() );
            ADD_FAILURE() << "accepted: " << name << " = " << value;
        }
        catch ( const std::runtime_error& e )
        {
            EXPECT_NE( std::string( e.what() ).find( what ), std::string::npos )
                << e.what();
            EXPECT_NE( std::string( e.what() ).find( damaged.string() ),
                       std::string::npos )
                << e.what();
        }
    };
    expectRefused( "/", "format", "rainslide-checkpoint-1",
                   "is not a rainslide checkpoint (rainslide-checkpoint-2)" );
    std::string changed = text;
    changed.replace( changed.find( "\"has_moved\":true" ), 16,
                     "\"has_moved\":false" );
    expectRefused( "/loop", "json", changed, "do not match their checksum" );
    expectRefused( "/loop", "json", text.substr( 0, text.size() / 2 ),
                   "the loop state is not valid JSON" );
    changed = text;
    changed.replace( changed.find( "\"stage\":2" ), 9, "\"stage\":\"2\"" );
    expectRefused( "/loop", "json", changed,
                   "loop state field 'stage' has the wrong type" );
}

//---------------------------------------------------------------------------//
// Writing goes through <file>.partial + rename: a failed write leaves the
// previous checkpoint intact and readable.
TEST( RestartFile, failed_write_keeps_the_previous_checkpoint )
{
    const fs::path dir = freshDir( "atomic" );
    const std::string file = ( dir / "checkpoint.h5" ).string();
    mpm::Checkpoint first;
    first.step = 11;
    mpm::writeCheckpoint( file, first );
    EXPECT_FALSE( fs::exists( file + ".partial" ) );
    // A folder in the way of the temporary file makes the next write fail.
    fs::create_directory( file + ".partial" );
    mpm::Checkpoint second;
    second.step = 22;
    EXPECT_THROW( mpm::writeCheckpoint( file, second ), std::runtime_error );
    EXPECT_EQ( mpm::readCheckpoint( file ).step, 11 );
    fs::remove( file + ".partial" );
    mpm::writeCheckpoint( file, second );
    EXPECT_EQ( mpm::readCheckpoint( file ).step, 22 );
    // Not a checkpoint: refused with the file's name.
    std::ofstream( dir / "other.h5" ) << "not hdf5";
    try
    {
        mpm::readCheckpoint( ( dir / "other.h5" ).string() );
        ADD_FAILURE() << "no error";
    }
    catch ( const std::runtime_error& e )
    {
        EXPECT_NE( std::string( e.what() ).find( "other.h5" ),
                   std::string::npos );
    }
}

//---------------------------------------------------------------------------//
// The case's keys identify it: a changed value is refused and named; a
// changed checkpoint interval, comment or layout is not a change.
TEST( RestartFile, changed_case_file_is_refused_with_the_key )
{
    const auto original = mpm::parseCase(
        blockCase( "courant_number = 0.5\ncheckpoint_interval_s = 0.1" ),
        "block.toml" );
    const auto reformatted = mpm::parseCase(
        "# a comment\n" +
            blockCase( "checkpoint_interval_s = 0.3\ncourant_number = 0.50" ),
        "block.toml" );
    const auto changed = mpm::parseCase(
        blockCase( "courant_number = 0.4", 0.25 ), "block_v2.toml" );
    EXPECT_EQ( original.fingerprint, reformatted.fingerprint );
    EXPECT_NE( original.fingerprint.find( "stages[1].name = 'more'" ),
               std::string::npos )
        << original.fingerprint;

    mpm::Checkpoint checkpoint;
    checkpoint.identity.case_name = original.name;
    checkpoint.identity.case_file = original.file;
    checkpoint.identity.case_fingerprint = original.fingerprint;
    auto now = checkpoint.identity;
    EXPECT_EQ( mpm::checkpointMismatch( checkpoint, "c.h5", now ), "" );
    now.case_fingerprint = reformatted.fingerprint;
    EXPECT_EQ( mpm::checkpointMismatch( checkpoint, "c.h5", now ), "" );
    now.case_file = changed.file;
    now.case_fingerprint = changed.fingerprint;
    const std::string why = mpm::checkpointMismatch( checkpoint, "c.h5", now );
    for ( const char* fragment :
          { "c.h5", "block.toml", "block_v2.toml",
            "solver.courant_number: 0.5 in the checkpoint, 0.4 now",
            "stages[0].duration_s: 0.2 in the checkpoint, 0.25 now" } )
        EXPECT_NE( why.find( fragment ), std::string::npos ) << fragment << "\n"
                                                             << why;
}

} // namespace
