#ifndef MPM_CASE_SCHEMA_HPP
#define MPM_CASE_SCHEMA_HPP

#include <case/mpm_case_config.hpp>
#include <io/mpm_case_diagnostics.hpp>
#include <io/mpm_toml_access.hpp>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
// Tables of scalar keys ([solver], [water]) declared once: each key's
// member of the config struct, range and unit serve reading it, the
// unknown-key check and the documentation test (tests/tst_case_schema.cpp:
// docs/case-file.md lists every key with its type and default). Internal to
// the case reader.
//---------------------------------------------------------------------------//

//! One key of a table read into Config: a number, a boolean or a choice
//! among names (stored as an enum).
template <class Config>
struct ConfigKey
{
    const char* name;
    double Config::*number; //!< null unless a number key
    bool Config::*flag;     //!< null unless a boolean key
    Range range;            //!< allowed numbers
    const char* unit;       //!< unit text of the messages
    //! A choice key: its names, and the enum's index in Config.
    const std::vector<std::string>* choices = nullptr;
    int ( *get_choice )( const Config& ) = nullptr;
    void ( *set_choice )( Config&, int ) = nullptr;
};

//! A number key.
template <class Config>
ConfigKey<Config> numberKey( const char* name, double Config::*member,
                             const Range& range, const char* unit )
{
    return { name, member, nullptr, range, unit };
}

//! A boolean key.
template <class Config>
ConfigKey<Config> flagKey( const char* name, bool Config::*member )
{
    return { name, nullptr, member, Range::any(), "" };
}

//! A choice key: one of `names`, stored as the enum `Member` of Config
//! (its values 0, 1, ... in the order of the names).
template <class Config, class Enum, Enum Config::*Member>
ConfigKey<Config> choiceKey( const char* name,
                             const std::vector<std::string>& names )
{
    ConfigKey<Config> key{ name, nullptr, nullptr, Range::any(), "" };
    key.choices = &names;
    key.get_choice = []( const Config& c )
    { return static_cast<int>( c.*Member ); };
    key.set_choice = []( Config& c, const int index )
    { c.*Member = static_cast<Enum>( index ); };
    return key;
}

//! The names of the declared keys, in their order.
template <class Config>
std::vector<std::string> keyNames( const std::vector<ConfigKey<Config>>& keys )
{
    std::vector<std::string> names;
    for ( const auto& key : keys )
        names.push_back( key.name );
    return names;
}

//! Reads the keys of table `r` (described as `where` in messages) into
//! `config`; keys left out keep their values, unknown keys are errors.
template <class Config>
void readConfigKeys( TableReader& r, const std::vector<ConfigKey<Config>>& keys,
                     const std::string& where, Config& config )
{
    r.checkKeys( keyNames( keys ), where );
    for ( const auto& key : keys )
        if ( key.number )
            config.*key.number =
                r.number( key.name, key.range, key.unit, Need::Optional )
                    .value_or( config.*key.number );
        else if ( key.choices )
        {
            if ( const auto index =
                     r.choice( key.name, *key.choices, Need::Optional ) )
                key.set_choice( config, *index );
        }
        else
            config.*key.flag = r.boolean( key.name, Need::Optional )
                                   .value_or( config.*key.flag );
}

//! The names of solver.scheme, in the order of TwoPhaseScheme.
const std::vector<std::string>& twoPhaseSchemeNames();

//! \brief The keys of [solver], in the order the messages list them.
const std::vector<ConfigKey<SolverConfig>>& solverKeys();

//! \brief The keys of [water].
const std::vector<ConfigKey<WaterConfig>>& waterKeys();

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_SCHEMA_HPP
