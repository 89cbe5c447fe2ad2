// The stage-loop state as JSON (io/mpm_stage_state_json.hpp): every field
// round-trips bit for bit, non-finite doubles included; a missing, unknown,
// mistyped or out-of-range field is refused, naming the file and the field.
#include <io/mpm_stage_state_json.hpp>
#include <mpm_test_loop_state.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using nlohmann::json;

using mpm_test::filledLoopState;

const double inf = std::numeric_limits<double>::infinity();

//! True if a and b have the same bits.
bool sameBits( const double a, const double b )
{
    return std::memcmp( &a, &b, sizeof a ) == 0;
}

//! Expects every leaf of `value` to differ from that of `fresh`.
void expectAllSet( const json& value, const json& fresh,
                   const std::string& path )
{
    if ( value.is_structured() )
    {
        ASSERT_EQ( value.size(), fresh.size() ) << path;
        for ( auto item = value.begin(); item != value.end(); ++item )
            if ( value.is_object() )
                expectAllSet( *item, fresh.at( item.key() ),
                              path + "." + item.key() );
            else
                expectAllSet( *item,
                              fresh.at( static_cast<std::size_t>(
                                  item - value.begin() ) ),
                              path + "[]" );
    }
    else
        EXPECT_NE( value.dump(), fresh.dump() )
            << path << " keeps its default value";
}

//! The message of the error parseStageLoopState throws for `j`.
std::string refusal( const json& j )
{
    try
    {
        mpm::parseStageLoopState( j.dump(), "run/checkpoint.h5" );
    }
    catch ( const std::runtime_error& e )
    {
        return e.what();
    }
    return "(accepted)";
}

} // namespace

//---------------------------------------------------------------------------//
// Every field survives the JSON text bit for bit, the text itself too.
TEST( StageStateJson, every_field_round_trips_exactly )
{
    const mpm::StageLoopState state = filledLoopState();
    // The test sets every field (of the JSON definitions).
    mpm::StageLoopState fresh;
    fresh.run.stages.resize( 2 );
    expectAllSet( json( state ), json( fresh ), "" );

    const std::string text = mpm::stageLoopStateJson( state );
    EXPECT_EQ( text.find( "null" ), std::string::npos ) << text;
    EXPECT_NE( text.find( "\"ke_ratio\":\"nan\"" ), std::string::npos );
    EXPECT_NE( text.find( "\"kinetic_energy_j\":\"inf\"" ), std::string::npos );
    const mpm::StageLoopState read =
        mpm::parseStageLoopState( text, "checkpoint.h5" );
    EXPECT_EQ( mpm::stageLoopStateJson( read ), text );

    EXPECT_EQ( read.stage, state.stage );
    EXPECT_EQ( read.stage_started, true );
    EXPECT_EQ( read.has_moved, true );
    EXPECT_EQ( read.run.interrupted, true );
    EXPECT_EQ( read.progress.stage, state.progress.stage );
    EXPECT_EQ( read.progress.step, state.progress.step );
    EXPECT_EQ( read.progress.active_points, state.progress.active_points );
    EXPECT_EQ( read.run.steps, state.run.steps );
    ASSERT_EQ( read.run.stages.size(), 2u );
    EXPECT_EQ( read.run.stages[1].name, "settle" );
    EXPECT_EQ( read.run.stages[1].points_not_below_static_speed,
               state.run.stages[1].points_not_below_static_speed );
    EXPECT_TRUE( std::isnan( read.stage_summary.ke_ratio ) );
    for ( const auto& [got, want] :
          { std::pair{ read.progress.time_s, state.progress.time_s },
            { read.progress.stage_duration_s, 1.0e300 },
            { read.progress.dt_s, 5.0e-324 },
            { read.progress.kinetic_energy_j, inf },
            { read.below_since, -0.0 },
            { read.ke_max, state.ke_max },
            { read.static_since, state.static_since },
            { read.next_checkpoint_s, state.next_checkpoint_s },
            { read.run.dt_min_s, state.run.dt_min_s },
            { read.run.stages[1].max_speed_m_per_s, -inf },
            { read.run.stages[0].dt_min_s, state.run.stages[0].dt_min_s },
            { read.run.stages[0].water.flow_in,
              state.run.stages[0].water.flow_in },
            { read.run.water.stored_start, state.run.water.stored_start },
            { read.stage_summary.water.runoff,
              state.stage_summary.water.runoff } } )
        EXPECT_TRUE( sameBits( got, want ) ) << got << " != " << want;
}

// nlohmann's text of a double reads back to the same bits: 100000 random
// bit patterns (the finite ones), subnormals and extremes among them.
TEST( StageStateJson, doubles_survive_the_text_bit_for_bit )
{
    std::vector<double> values = { 5.0e-324,
                                   -0.0,
                                   1.0e300,
                                   std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::epsilon() };
    std::uint64_t state = 2026; // a fixed LCG
    while ( values.size() < 100000 )
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        double value = 0.0;
        std::memcpy( &value, &state, sizeof value );
        if ( std::isfinite( value ) )
            values.push_back( value );
    }
    const auto read = json::parse( json( values ).dump() );
    ASSERT_EQ( read.size(), values.size() );
    for ( std::size_t k = 0; k < values.size(); ++k )
        ASSERT_TRUE( sameBits( read[k].get<double>(), values[k] ) )
            << json( values[k] ).dump();
}

//---------------------------------------------------------------------------//
// A missing, unknown, mistyped or out-of-range field, twice a key or text
// that is not JSON: refused, naming the file and the field.
TEST( StageStateJson, bad_fields_are_refused_by_name )
{
    const json good =
        json::parse( mpm::stageLoopStateJson( filledLoopState() ) );
    EXPECT_EQ( refusal( good ), "(accepted)" );
    const auto expectRefused = [&]( const json& j, const std::string& what )
    {
        const std::string message = refusal( j );
        EXPECT_EQ( message.rfind( "checkpoint 'run/checkpoint.h5': ", 0 ), 0u )
            << message;
        EXPECT_NE( message.find( what ), std::string::npos ) << message;
    };
    json j = good;
    j["run"]["stages"][1].erase( "steps" );
    expectRefused( j, "field 'run.stages[1].steps' is missing" );
    j = good;
    j.erase( "ke_max" );
    expectRefused( j, "field 'ke_max' is missing" );
    j = good;
    j["progress"]["wall_s"] = 1.0;
    expectRefused( j, "unknown loop state field 'progress.wall_s'" );
    j = good;
    j["has_moved"] = 1;
    expectRefused( j, "field 'has_moved' has the wrong type: expected true "
                      "or false, found number 1" );
    j = good;
    j["run"]["stages"][0]["water"]["runoff"] = "much";
    expectRefused( j, "field 'run.stages[0].water.runoff' has the wrong type" );
    j = good;
    j["stage_summary"]["ke_ratio"] = nullptr;
    expectRefused( j, "field 'stage_summary.ke_ratio' has the wrong type" );
    j = good;
    j["progress"]["step"] = 2.5;
    expectRefused( j, "field 'progress.step' has the wrong type: expected an "
                      "integer, found number 2.5" );
    j = good;
    j["stage"] = -1;
    expectRefused( j, "field 'stage' has the wrong type: expected a "
                      "non-negative integer" );
    j = good;
    j["progress"]["stage_index"] = 1LL << 40;
    expectRefused( j, "field 'progress.stage_index' is out of range: "
                      "1099511627776" );
    j = good;
    j["run"]["stages"] = json::object();
    expectRefused( j, "field 'run.stages' has the wrong type: expected an "
                      "array, found object" );
    expectRefused( json::array(), "the loop state has the wrong type" );

    const std::string text = good.dump();
    for ( const auto& [bad, what] :
          { std::pair<std::string, std::string>{ text.substr( 0, 100 ),
                                                 "is not valid JSON" },
            { "", "is not valid JSON" },
            { "{\"stage\":1," + text.substr( 1 ), "the key 'stage' twice" } } )
    {
        try
        {
            mpm::parseStageLoopState( bad, "run/checkpoint.h5" );
            ADD_FAILURE() << "accepted: " << bad;
        }
        catch ( const std::runtime_error& e )
        {
            EXPECT_NE( std::string( e.what() ).find( what ), std::string::npos )
                << e.what();
            EXPECT_NE( std::string( e.what() ).find( "run/checkpoint.h5" ),
                       std::string::npos );
        }
    }
}
