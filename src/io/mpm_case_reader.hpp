#ifndef MPM_CASE_READER_HPP
#define MPM_CASE_READER_HPP

#include <case/mpm_case_config.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief An invalid or unreadable case file.

  what() is the full user-facing text: one line per error, each as
  "file:line:column: error: key 'materials[0].poisson_ratio': expected a
  number in [0, 0.5), found 0.7", in file order (the first line is the
  first problem in the file).
*/
class CaseError : public std::runtime_error
{
  public:
    explicit CaseError( const std::string& message )
        : std::runtime_error( message )
    {
    }
};

//---------------------------------------------------------------------------//
/*!
  \brief Read and validate a TOML case file (schema: docs/case-file.md).

  Every key is checked (unknown keys, types, ranges, references between
  materials, bodies and stages, polygon validity, grid extent, the keys
  allowed or required by case.analysis) before the configuration is
  returned. Derived data are filled in:
  BodyConfig::material_id and, per stage, the effective materials (case
  materials with the stage's overrides applied) and boundaries (the case
  boundaries unless the stage gives its own list).

  \param path Case file; it is also CaseConfig::file and the file name in
  error messages.
  \param overrides `--set KEY=VALUE` texts applied to the case (includes
  resolved) before it is checked (Impl::applyOverrides); kept in
  CaseConfig::overrides.
  \throw CaseError if the file cannot be read or is invalid.
*/
CaseConfig readCaseFile( const std::string& path,
                         const std::vector<std::string>& overrides = {} );

//---------------------------------------------------------------------------//
/*!
  \brief Validate a case given as TOML text (see readCaseFile).

  \param toml_text The case file contents.
  \param file_name Name used in error messages and as CaseConfig::file.
  \param overrides As for readCaseFile.
  \throw CaseError if the text is not valid TOML or not a valid case.
*/
CaseConfig parseCase( const std::string& toml_text,
                      const std::string& file_name,
                      const std::vector<std::string>& overrides = {} );

} // namespace mpm

#endif // MPM_CASE_READER_HPP
