#ifndef MPM_CASE_KEYS_HPP
#define MPM_CASE_KEYS_HPP

#include <io/mpm_toml_access.hpp>

#include <string>
#include <vector>

namespace mpm
{
namespace Impl
{
//---------------------------------------------------------------------------//
/*!
  \brief The keys of one table of a case file, declared once: the reader
  checks a table's keys against them (unknown keys are errors) and the test
  CaseSchema.every_table_is_documented checks that the table of the
  section `table` of docs/case-file.md lists exactly these keys.
*/
struct CaseTableKeys
{
    std::string table; //!< as docs/case-file.md heads it: "[grid]"
    std::vector<std::string> keys;
};

//! Every documented table of a case file with its keys.
const std::vector<CaseTableKeys>& caseTableKeys();

//! The keys of `table` (one of caseTableKeys; std::logic_error otherwise).
const std::vector<std::string>& keysOf( const std::string& table );

//! Checks the keys of table reader r against keysOf(table).
inline void checkTableKeys( TableReader& r, const std::string& table )
{
    r.checkKeys( keysOf( table ), table );
}

//! forEachTable over an array of the tables `table` ("[[bodies]]"): each
//! checked against keysOf(table) and named `table` in the messages.
template <class Read>
void forEachTableOf( const std::string& table, const toml::array& array,
                     const std::string& prefix, Diagnostics& diag, Read&& read )
{
    forEachTable( array, prefix, diag, keysOf( table ), table, read );
}

//! The items read(r, item) reads from an array of the tables `table`
//! (forEachTableOf), one default-constructed T per table.
template <class T, class Read>
std::vector<T> readTablesOf( const std::string& table, const toml::array& array,
                             const std::string& prefix, Diagnostics& diag,
                             Read&& read )
{
    std::vector<T> items;
    forEachTableOf( table, array, prefix, diag,
                    [&]( TableReader& r )
                    {
                        T item;
                        read( r, item );
                        items.push_back( item );
                    } );
    return items;
}

} // namespace Impl
} // namespace mpm

#endif // MPM_CASE_KEYS_HPP
