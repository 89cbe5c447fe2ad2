// The checkpoint file: the loop state round-trips, a failed write keeps the
// previous checkpoint, a checkpoint of a changed case file is refused.
#include <mpm_test_restart.hpp>

#include <io/mpm_case_fingerprint.hpp>
#include <io/mpm_case_reader.hpp>
#include <io/mpm_checkpoint.hpp>
#include <records/mpm_stage_state.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace
{
namespace fs = std::filesystem;

using namespace mpm_test::restart;

//---------------------------------------------------------------------------//
//! Every field of a loop state as text (doubles in hex: exact).
std::vector<std::string> loopFields( const mpm::StageLoopState& state )
{
    std::vector<std::string> out;
    const auto text = [&]( const std::string& name, const auto& value )
    {
        using T = std::decay_t<decltype( value )>;
        std::ostringstream line;
        line << name << " = ";
        if constexpr ( std::is_same_v<T, double> )
            line << std::hexfloat << value;
        else
            line << value;
        out.push_back( line.str() );
    };
    mpm::visitStageLoopState(
        state,
        [&]( const std::string& name, const auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<mpm::StageSummary>> )
            {
                for ( std::size_t k = 0; k < value.size(); ++k )
                    mpm::visitStageSummary(
                        value[k], [&]( const std::string& field, const auto& v )
                        { text( name + std::to_string( k ) + field, v ); } );
            }
            else
                text( name, value );
        } );
    return out;
}

// Every field of the loop state survives the file, with distinct values.
TEST( RestartFile, loop_state_round_trips )
{
    mpm::StageLoopState state;
    int k = 0;
    const auto fill = [&]( auto& value )
    {
        using T = std::decay_t<decltype( value )>;
        ++k;
        if constexpr ( std::is_same_v<T, double> )
            value = 1.0 / 3.0 + k;
        else if constexpr ( std::is_same_v<T, std::string> )
            value = "text " + std::to_string( k );
        else if constexpr ( std::is_same_v<T, bool> )
            value = k % 2 == 0;
        else
            value = static_cast<T>( 1000 + k );
    };
    mpm::visitStageLoopState(
        state,
        [&]( const std::string&, auto& value )
        {
            using T = std::decay_t<decltype( value )>;
            if constexpr ( std::is_same_v<T, std::vector<mpm::StageSummary>> )
            {
                value.resize( 2 );
                for ( auto& summary : value )
                    mpm::visitStageSummary( summary,
                                            [&]( const std::string&, auto& v )
                                            { fill( v ); } );
            }
            else
                fill( value );
        } );
    mpm::Checkpoint checkpoint;
    checkpoint.loop = state;
    checkpoint.identity.case_fingerprint = "a = 1\n";
    checkpoint.load_groups = { { 0, 2 }, { 1 } };
    checkpoint.load_counts = { 3, 4, 5 };
    checkpoint.snapshots = { 7, 123, 0.25 };
    const fs::path file = freshDir( "round_trip" ) / "checkpoint.h5";
    mpm::writeCheckpoint( file.string(), checkpoint );
    const mpm::Checkpoint read = mpm::readCheckpoint( file.string() );
    EXPECT_EQ( loopFields( read.loop ), loopFields( state ) );
    EXPECT_EQ( read.load_groups, checkpoint.load_groups );
    EXPECT_EQ( read.load_counts, checkpoint.load_counts );
    EXPECT_EQ( read.identity.case_fingerprint, "a = 1\n" );
    EXPECT_EQ( read.snapshots.count, 7 );
    EXPECT_EQ( read.snapshots.last_step, 123 );
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
