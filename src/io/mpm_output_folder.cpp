#include <io/mpm_output_folder.hpp>

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
std::string unsafeOutputFolder( const std::string& out_dir )
{
    namespace fs = std::filesystem;
    const std::string expected =
        "expected a folder of its own for the results, found ";
    if ( out_dir.empty() )
        return expected + "an empty path";
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical( fs::absolute( out_dir ), ec );
    if ( ec )
        return expected + "a path that cannot be resolved (" + ec.message() +
               ")";
    const std::string text = folder.string();
    if ( folder == folder.root_path() )
        return expected + "the root folder '" + text + "'";
    const std::vector<std::string> system_folders = {
        "/bin",  "/boot", "/dev", "/etc", "/lib", "/lib64",
        "/proc", "/sbin", "/sys", "/usr", "/var" };
    for ( const std::string& system : system_folders )
        if ( text == system )
            return expected + "the system folder '" + text + "'";
    for ( const std::string system : { "/dev/", "/proc/", "/sys/" } )
        if ( text.rfind( system, 0 ) == 0 )
            return expected + "a folder inside '" + system + "' ('" + text +
                   "')";
    if ( const char* home = std::getenv( "HOME" ) )
        if ( *home && fs::weakly_canonical( home, ec ) == folder && !ec )
            return expected + "the home folder '" + text +
                   "' (use a folder inside it)";
    if ( fs::exists( folder, ec ) && !fs::is_directory( folder, ec ) )
        return expected + "'" + text + "', which is not a folder";
    return "";
}

//---------------------------------------------------------------------------//
std::string caseFilesInOutputFolder( const std::string& out_dir,
                                     const std::string& case_file )
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical( fs::absolute( out_dir ), ec );
    if ( ec )
        return "";
    const fs::path case_folder =
        fs::weakly_canonical( fs::absolute( case_file ), ec ).parent_path();
    const std::string expected =
        "expected a folder of its own for the results, found ";
    if ( !ec && folder == case_folder )
        return expected + "the folder of the case file '" + case_file + "' ('" +
               folder.string() + "')";
    if ( !fs::is_directory( folder, ec ) )
        return "";
    for ( fs::directory_iterator it( folder, ec ), end; !ec && it != end;
          it.increment( ec ) )
        if ( it->path().extension() == ".toml" )
            return expected + "a folder that holds case files ('" +
                   it->path().string() + "')";
    return "";
}

} // namespace mpm
