#include <io/mpm_case_analysis.hpp>
#include <io/mpm_case_conditions.hpp>
#include <io/mpm_case_file.hpp>
#include <io/mpm_case_fingerprint.hpp>
#include <io/mpm_case_include.hpp>
#include <io/mpm_case_keys.hpp>
#include <io/mpm_case_limits.hpp>
#include <io/mpm_case_materials.hpp>
#include <io/mpm_case_overrides.hpp>
#include <io/mpm_case_pore_pressure.hpp>
#include <io/mpm_case_probes.hpp>
#include <io/mpm_case_reader.hpp>
#include <io/mpm_case_schema.hpp>
#include <io/mpm_case_shapes.hpp>
#include <io/mpm_toml_access.hpp>
#include <io/mpm_toml_prescan.hpp>

#include <algorithm>
#include <map>
#include <sstream>

namespace mpm
{
namespace
{
using Impl::Diagnostics;
using Impl::finishMaterial;
using Impl::MaterialDraft;
using Impl::Need;
using Impl::Range;
using Impl::readMaterialValues;
using Impl::TableReader;

//---------------------------------------------------------------------------//
// Reads one case file into a CaseConfig, collecting every error.
class CaseParser
{
  public:
    CaseParser( Diagnostics& diag, CaseConfig& config )
        : _diag( diag )
        , _config( config )
    {
    }

    void parse( const toml::table& root_table )
    {
        TableReader root( root_table, "", _diag );
        root.checkKeys( { "case", "water", "grid", "particles", "materials",
                          "bodies", "boundaries", "solver", "stages",
                          "probes" },
                        "the top level of a case file" );
        _analysis = Impl::readCaseTable( root, _diag, _config );
        parseWater( root );
        parseGrid( root );
        if ( const auto* t = root.subTable( "particles", Need::Optional ) )
        {
            TableReader r( *t, "particles", _diag );
            Impl::checkTableKeys( r, "[particles]" );
            _config.points_per_cell_per_direction =
                r.integer( "points_per_cell", 1, 6, Need::Optional )
                    .value_or( _config.points_per_cell_per_direction );
        }
        parseMaterials( root );
        parseBodies( root );
        if ( const auto* arr = root.tableArray( "boundaries", Need::Optional,
                                                "[[boundaries]]" ) )
            _config.boundaries = Impl::readBoundaries(
                *arr, "boundaries", _analysis, grid(), _diag );
        if ( const auto* t = root.subTable( "solver", Need::Optional ) )
        {
            TableReader r( *t, "solver", _diag );
            Impl::readConfigKeys( r, Impl::solverKeys(), "[solver]",
                                  _config.solver );
            _config.solver.bbar_given = r.find( "bbar" ) != nullptr;
            // The semi-implicit and seepage schemes solve for the pore
            // pressure.
            if ( _config.solver.scheme != TwoPhaseScheme::Explicit )
                Impl::rejectIfDry( r, "scheme", _analysis );
            // The auto scheme's two schemes choose steps of their own.
            const toml::node* dt_node = r.find( "dt_s" );
            if ( _config.solver.scheme == TwoPhaseScheme::Auto && dt_node &&
                 _config.solver.dt_s > 0.0 )
            {
                std::ostringstream what;
                what << "expected 0 (the automatic steps) with scheme = "
                        "\"auto\", whose quasi-static and semi-implicit steps "
                        "each choose their own, found "
                     << _config.solver.dt_s << " s";
                r.diag().keyError( *dt_node, r.keyPath( "dt_s" ), what.str() );
            }
        }
        parseStages( root );
        if ( const auto* t = root.subTable( "probes", Need::Optional ) )
            _config.probes = Impl::readProbes( *t, grid(), _diag );
    }

  private:
    //! The grid if [grid] was read without errors, else null.
    const GridConfig* grid() const
    {
        return _grid_ok ? &_config.grid : nullptr;
    }

    //! Report a reference to a material that is not defined.
    void unknownMaterial( const toml::source_region& where,
                          const std::string& path, const std::string& name )
    {
        std::string text = "key '" + path + "': unknown material '" + name +
                           "'; the materials defined in [[materials]] are " +
                           Impl::quotedList( _material_names );
        const std::string guess = Impl::closestWord( name, _material_names );
        if ( !guess.empty() )
            text += "; did you mean '" + guess + "'?";
        _diag.error( where, text );
    }

    void parseWater( TableReader& root )
    {
        const toml::node* node = root.find( "water" );
        if ( !node )
            return;
        if ( Impl::isDry( _analysis ) )
        {
            _diag.keyError( *node, "water", Impl::twoPhaseOnlyText() );
            return;
        }
        const auto* t = root.subTable( "water", Need::Optional );
        if ( !t )
            return;
        TableReader r( *t, "water", _diag );
        Impl::readConfigKeys( r, Impl::waterKeys(), "[water]", _config.water );
    }

    void parseGrid( TableReader& root )
    {
        const auto* t = root.subTable( "grid", Need::Required );
        if ( !t )
            return;
        TableReader r( *t, "grid", _diag );
        Impl::checkTableKeys( r, "[grid]" );
        const auto origin = r.point( "origin_m", "m", Need::Required );
        const auto h =
            r.number( "cell_size_m", Range::above( 0.0 ), "m", Need::Required );
        const std::string expected = "an array [nx, ny] of integers >= 1";
        const toml::node* cells = r.node( "cells", Need::Required, expected );
        bool cells_ok = false;
        if ( cells && ( !cells->is_array() || cells->as_array()->size() != 2 ) )
            _diag.mismatch( *cells, "grid.cells", expected );
        else if ( cells )
        {
            cells_ok = true;
            for ( int d = 0; d < 2; ++d )
            {
                const toml::node& c = *cells->as_array()->get( d );
                const auto* i = c.as_integer();
                if ( i && i->get() >= 1 && i->get() <= 1000000 )
                    _config.grid.cells[d] = static_cast<int>( i->get() );
                else
                {
                    _diag.mismatch( c,
                                    "grid.cells[" + std::to_string( d ) + "]",
                                    "an integer in 1..1000000" );
                    cells_ok = false;
                }
            }
            const long long total =
                static_cast<long long>( _config.grid.cells[0] ) *
                _config.grid.cells[1];
            if ( cells_ok && total > Impl::max_grid_cells )
            {
                _diag.keyError( *cells, "grid.cells",
                                "expected at most " +
                                    std::to_string( Impl::max_grid_cells ) +
                                    " cells (nx * ny), found " +
                                    std::to_string( total ) );
                cells_ok = false;
            }
        }
        if ( origin )
            _config.grid.origin_m = *origin;
        if ( h )
            _config.grid.cell_size_m = *h;
        _grid_ok = origin && h && cells_ok;
    }

    void parseMaterials( TableReader& root )
    {
        const auto* arr =
            root.tableArray( "materials", Need::Required, "[[materials]]" );
        if ( !arr )
            return;
        if ( arr->empty() )
            _diag.mismatch( *arr, "materials",
                            "at least one material ([[materials]] table)" );
        std::map<std::string, std::string> first_path;
        Impl::forEachTableOf(
            "[[materials]]", *arr, "materials", _diag,
            [&]( TableReader& r )
            {
                MaterialDraft draft;
                if ( const auto name = r.string( "name", Need::Required ) )
                {
                    draft.name = *name;
                    Impl::checkUniqueName( r, *name, first_path,
                                           "material name",
                                           "; material names must be unique" );
                }
                readMaterialValues( r, draft, Need::Required, _analysis );
                const auto material = finishMaterial( draft, r, _analysis );
                if ( material )
                    _config.materials.push_back( *material );
                _drafts.push_back( draft );
                _material_names.push_back( draft.name );
                _materials_ok =
                    _materials_ok && material && !draft.name.empty();
            } );
    }

    //! Index of a material by name, or -1.
    int materialIndex( const std::string& name ) const
    {
        const auto it =
            std::find( _material_names.begin(), _material_names.end(), name );
        return it == _material_names.end()
                   ? -1
                   : static_cast<int>( it - _material_names.begin() );
    }

    void parseBodies( TableReader& root )
    {
        const auto* arr =
            root.tableArray( "bodies", Need::Required, "[[bodies]]" );
        if ( !arr )
            return;
        if ( arr->empty() )
            _diag.mismatch( *arr, "bodies", "at least one [[bodies]] table" );
        Impl::forEachTableOf(
            "[[bodies]]", *arr, "bodies", _diag,
            [&]( TableReader& r )
            {
                const std::string& path = r.path();
                BodyConfig body;
                if ( const auto name = r.string( "material", Need::Required ) )
                {
                    body.material = *name;
                    body.material_id = materialIndex( *name );
                    if ( body.material_id < 0 && !_material_names.empty() )
                        unknownMaterial( r.find( "material" )->source(),
                                         path + ".material", *name );
                }
                if ( auto polygon =
                         r.points( "polygon_m", 3, "m", Need::Required,
                                   Impl::max_polygon_vertices ) )
                {
                    Impl::checkBodyPolygon( *polygon, *r.find( "polygon_m" ),
                                            path + ".polygon_m", grid(),
                                            _diag );
                    body.polygon_m = *polygon;
                }
                Impl::readInitialPorePressure( r, _analysis, body );
                _config.bodies.push_back( body );
            } );
    }

    void parseStages( TableReader& root )
    {
        const auto* arr =
            root.tableArray( "stages", Need::Required, "[[stages]]" );
        if ( !arr )
            return;
        if ( arr->empty() )
            _diag.mismatch( *arr, "stages", "at least one [[stages]] table" );
        std::map<std::string, std::string> first_path;
        Impl::forEachTableOf(
            "[[stages]]", *arr, "stages", _diag,
            [&]( TableReader& r )
            {
                const std::string& path = r.path();
                StageConfig stage;
                if ( const auto name = r.string( "name", Need::Required ) )
                {
                    stage.name = *name;
                    Impl::checkUniqueName( r, *name, first_path, "stage name",
                                           "" );
                }
                const auto type = r.choice(
                    "type", { "quasi_static", "dynamic" }, Need::Required );
                if ( type )
                    stage.type = static_cast<StageType>( *type );
                Impl::readStageTiming( r, path, type.has_value(), stage,
                                       _diag );
                stage.materials = _config.materials;
                if ( const auto* t = r.subTable( "materials", Need::Optional ) )
                    parseOverrides( *t, path + ".materials", stage );
                stage.boundaries = _config.boundaries;
                if ( const auto* b = r.tableArray( "boundaries", Need::Optional,
                                                   "[[stages.boundaries]]" ) )
                    stage.boundaries = Impl::readBoundaries(
                        *b, path + ".boundaries", _analysis, grid(), _diag );
                if ( !Impl::rejectIfDry( r, "inflows", _analysis ) )
                    if ( const auto* f = r.tableArray(
                             "inflows", Need::Optional, "[[stages.inflows]]" ) )
                        stage.inflows = Impl::readInflows(
                            *f, path + ".inflows", grid(), _diag );
                if ( !Impl::rejectIfDry( r, "pore_pressures", _analysis ) )
                    if ( const auto* p =
                             r.tableArray( "pore_pressures", Need::Optional,
                                           "[[stages.pore_pressures]]" ) )
                        stage.pore_pressures = Impl::readPorePressures(
                            *p, path + ".pore_pressures", _diag );
                if ( const auto* l = r.tableArray( "loads", Need::Optional,
                                                   "[[stages.loads]]" ) )
                    stage.loads = Impl::readLoads( *l, path + ".loads", _diag );
                _config.stages.push_back( stage );
            } );
    }

    //! Apply [stages.materials.<name>] tables to the stage's materials.
    void parseOverrides( const toml::table& overrides, const std::string& path,
                         StageConfig& stage )
    {
        for ( auto&& [key, node] : overrides )
        {
            const std::string name( key.str() );
            const std::string sub_path = Impl::joinPath( path, name );
            const int id = materialIndex( name );
            if ( id < 0 )
            {
                unknownMaterial( key.source(), sub_path, name );
                continue;
            }
            if ( !node.is_table() )
            {
                const std::string expected =
                    "a table of material parameters [" + sub_path + "]";
                _diag.mismatch( node, sub_path, expected );
                continue;
            }
            TableReader r( *node.as_table(), sub_path, _diag );
            auto keys = Impl::keysOf( "[[materials]]" );
            keys.erase( std::find( keys.begin(), keys.end(), "name" ) );
            r.checkKeys( keys, "a stage material override", { "name" } );
            if ( const auto* n = r.find( "name" ) )
                _diag.keyError( *n, r.keyPath( "name" ),
                                "a stage cannot rename a material; the table "
                                "name selects the material ('" +
                                    name + "')" );
            MaterialDraft draft = _drafts[id];
            readMaterialValues( r, draft, Need::Optional, _analysis );
            if ( !_materials_ok )
                continue;
            if ( const auto material = finishMaterial( draft, r, _analysis ) )
                stage.materials[id] = *material;
        }
    }

    Diagnostics& _diag;
    CaseConfig& _config;
    bool _grid_ok = false;
    bool _materials_ok = true;
    Impl::Analysis _analysis = AnalysisType::Dry;
    std::vector<MaterialDraft> _drafts;
    std::vector<std::string> _material_names;
};

} // namespace

//---------------------------------------------------------------------------//
CaseConfig parseCase( const std::string& toml_text,
                      const std::string& file_name,
                      const std::vector<std::string>& overrides )
{
    toml::table root;
    Diagnostics prescan( file_name );
    if ( !Impl::prescanToml( toml_text, file_name, prescan ) )
        throw CaseError( prescan.report() );
    try
    {
        root = toml::parse( std::string_view( toml_text ),
                            std::string_view( file_name ) );
    }
    catch ( const toml::parse_error& e )
    {
        Diagnostics syntax( file_name );
        syntax.error( e.source(),
                      "invalid TOML: " + std::string( e.description() ) );
        throw CaseError( syntax.report() );
    }

    CaseConfig config;
    config.file = file_name;
    Diagnostics diag( file_name );
    Impl::resolveIncludes( root, file_name, diag, toml_text.size() );
    if ( diag.empty() )
        Impl::applyOverrides( root, overrides, diag );
    if ( !diag.empty() ) // without an included file, the rest is noise
        throw CaseError( diag.report() );
    CaseParser( diag, config ).parse( root );
    if ( !diag.empty() )
        throw CaseError( diag.report() );
    config.fingerprint = caseFingerprint( root );
    config.overrides = overrides;
    config.warnings = diag.warnings();
    return config;
}

//---------------------------------------------------------------------------//
CaseConfig readCaseFile( const std::string& path,
                         const std::vector<std::string>& overrides )
{
    std::string text;
    try
    {
        text = Impl::readRegularFile( path, Impl::max_case_file_bytes );
    }
    catch ( const Impl::CaseFileError& e )
    {
        throw CaseError( path +
                         ": error: cannot open the case file: " + e.what() );
    }
    return parseCase( text, path, overrides );
}

} // namespace mpm
