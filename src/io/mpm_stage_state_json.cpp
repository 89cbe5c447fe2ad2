#include <io/mpm_stage_state_json.hpp>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mpm
{
namespace
{
using nlohmann::json;

// The non-finite doubles by their names in the JSON text.
const std::pair<const char*, double> non_finite[] = {
    { "nan", std::numeric_limits<double>::quiet_NaN() },
    { "inf", std::numeric_limits<double>::infinity() },
    { "-inf", -std::numeric_limits<double>::infinity() } };

// Replaces every non-finite number in `j` by its name.
void nameNonFinite( json& j )
{
    if ( j.is_number_float() && !std::isfinite( j.get<double>() ) )
    {
        const double value = j.get<double>();
        j = std::isnan( value ) ? "nan" : value > 0.0 ? "inf" : "-inf";
    }
    else if ( j.is_structured() )
        for ( json& child : j )
            nameNonFinite( child );
}

// "a.b" (or "b" at the top), the path of member `key` of field `path`.
std::string member( const std::string& path, const std::string& key )
{
    return path.empty() ? key : path + "." + key;
}

// What a value of the type of `shape` is called in messages.
const char* expected( const json& shape )
{
    // A list, not a std::map: nlohmann's operator< on value_t ranks the
    // three number types equal.
    using T = json::value_t;
    static const std::pair<T, const char*> names[] = {
        { T::number_float, "a number (or \"nan\", \"inf\", \"-inf\")" },
        { T::number_integer, "an integer" },
        { T::number_unsigned, "a non-negative integer" },
        { T::boolean, "true or false" },
        { T::string, "a string" },
        { T::array, "an array" } };
    for ( const auto& [type, name] : names )
        if ( type == shape.type() )
            return name;
    return "an object";
}

// What `j` is, for messages: its type and, if not structured, its value.
std::string found( const json& j )
{
    if ( j.is_structured() || j.is_null() )
        return j.type_name();
    const std::string text = j.dump();
    return std::string( j.type_name() ) + " " +
           ( text.size() <= 40 ? text : text.substr( 0, 37 ) + "..." );
}

//---------------------------------------------------------------------------//
// Checks the JSON of a loop state against that of a fresh one, refusing
// what parseStageLoopState refuses with the checkpoint file's name.
class LoopStateCheck
{
  public:
    explicit LoopStateCheck( const std::string& file )
        : _file( file )
    {
    }

    // Throws std::runtime_error "checkpoint '<file>': <what>".
    [[noreturn]] void fail( const std::string& what ) const
    {
        throw std::runtime_error( "checkpoint '" + _file + "': " + what );
    }

    // "loop state field '<path>'" (the whole state for "").
    static std::string field( const std::string& path )
    {
        return path.empty() ? "the loop state"
                            : "loop state field '" + path + "'";
    }

    // Checks that `j` (field `path`) has the type and the members of
    // `shape`; turns "nan", "inf" and "-inf" into numbers where a number
    // is expected. An array is checked against the first element of
    // `shape`'s array.
    void check( json& j, const json& shape, const std::string& path ) const
    {
        if ( shape.is_number_float() && j.is_string() )
            for ( const auto& [name, value] : non_finite )
                if ( j.get_ref<const std::string&>() == name )
                {
                    j = value;
                    break;
                }
        const bool ok = shape.is_number_float()     ? j.is_number()
                        : shape.is_number_integer() ? j.is_number_integer()
                                                    : j.type() == shape.type();
        if ( !ok || ( shape.is_number_unsigned() && !j.is_number_unsigned() ) )
            fail( field( path ) + " has the wrong type: expected " +
                  expected( shape ) + ", found " + found( j ) );
        if ( j.is_object() )
        {
            for ( const auto& item : j.items() )
                if ( !shape.contains( item.key() ) )
                    fail( "unknown " + field( member( path, item.key() ) ) );
            for ( const auto& item : shape.items() )
            {
                const std::string sub = member( path, item.key() );
                if ( !j.contains( item.key() ) )
                    fail( field( sub ) + " is missing (written by another "
                                         "version of rainslide?)" );
                check( j[item.key()], item.value(), sub );
            }
        }
        else if ( j.is_array() )
            for ( std::size_t k = 0; k < j.size(); ++k )
            {
                const std::string sub = path + "[" + std::to_string( k ) + "]";
                if ( shape.empty() )
                    fail( "unexpected " + field( sub ) );
                check( j[k], shape[0], sub );
            }
    }

  private:
    std::string _file;
};

// The first value in `a` that differs from `b` (of the same shape), with
// its path in `path`; nullptr if none does.
const json* firstDifference( const json& a, const json& b, std::string& path )
{
    if ( !a.is_structured() )
        return a == b ? nullptr : &a;
    const std::string here = path;
    std::size_t k = 0;
    for ( auto item = a.begin(); item != a.end(); ++item, ++k )
    {
        const bool object = a.is_object();
        path = object ? member( here, item.key() )
                      : here + "[" + std::to_string( k ) + "]";
        const json& other = object ? b.at( item.key() ) : b.at( k );
        if ( const json* differs = firstDifference( *item, other, path ) )
            return differs;
    }
    path = here;
    return nullptr;
}

} // namespace

//---------------------------------------------------------------------------//
std::string stageLoopStateJson( const StageLoopState& state )
{
    json j = state;
    nameNonFinite( j );
    try
    {
        return j.dump();
    }
    catch ( const json::exception& e )
    {
        throw std::runtime_error( std::string( "mpm::writeCheckpoint: the "
                                               "loop state: " ) +
                                  e.what() );
    }
}

//---------------------------------------------------------------------------//
StageLoopState parseStageLoopState( const std::string& text,
                                    const std::string& file )
{
    const LoopStateCheck checker( file );
    // Refuses a key twice in one object (nlohmann would keep the last).
    std::vector<std::set<std::string>> keys;
    const json::parser_callback_t unique =
        [&]( int, const json::parse_event_t event, json& parsed )
    {
        if ( event == json::parse_event_t::object_start )
            keys.emplace_back();
        else if ( event == json::parse_event_t::object_end )
            keys.pop_back();
        else if ( event == json::parse_event_t::key &&
                  !keys.back().insert( parsed.get<std::string>() ).second )
            checker.fail( "the loop state has the key '" +
                          parsed.get<std::string>() + "' twice" );
        return true;
    };
    json j;
    try
    {
        j = json::parse( text, unique );
    }
    catch ( const json::exception& e )
    {
        checker.fail( std::string( "the loop state is not valid JSON (" ) +
                      e.what() + ")" );
    }
    // The shape of a state, with one finished stage for the array's.
    StageLoopState fresh;
    fresh.run.stages.resize( 1 );
    checker.check( j, json( fresh ), "" );
    StageLoopState state;
    try
    {
        state = j.get<StageLoopState>();
    }
    catch ( const json::exception& e )
    {
        checker.fail( std::string( "the loop state: " ) + e.what() );
    }
    // An integer that does not fit its field comes back changed.
    json back = state;
    nameNonFinite( back );
    nameNonFinite( j );
    std::string path;
    if ( const json* value = firstDifference( j, back, path ) )
        checker.fail( LoopStateCheck::field( path ) +
                      " is out of range: " + value->dump() );
    return state;
}

} // namespace mpm
