#ifndef MPM_CASE_FINGERPRINT_HPP
#define MPM_CASE_FINGERPRINT_HPP

#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Canonical text of a parsed case (includes resolved): one line
  "dotted.path = value" per key, sorted, arrays of tables indexed
  ("stages[1].duration_s = 10.0"). Comments, layout and key order do not
  change it; any value does. solver.checkpoint_interval_s is left out:
  it does not change the results, and a run may be restarted with another
  interval. A checkpoint stores it to recognise its case.
*/
std::string caseFingerprint( const toml::table& root );

//! 64-bit FNV-1a hash of a text (stable across builds and platforms).
std::uint64_t fnv1aHash( const std::string& text );

//! The hash as 16 hexadecimal digits.
std::string hashText( std::uint64_t hash );

/*!
  \brief What differs between two fingerprints, one line per key
  ("  solver.courant_number: 0.5 in the checkpoint, 0.4 now"), at most
  `max_lines` (then "  ... and N more"). Empty if they are equal.
*/
std::string fingerprintDifferences( const std::string& checkpoint,
                                    const std::string& now,
                                    std::size_t max_lines = 10 );

} // namespace mpm

#endif // MPM_CASE_FINGERPRINT_HPP
