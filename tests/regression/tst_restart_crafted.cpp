// Checkpoints whose values were rewritten with valid checksums (as a script
// editing the file with h5py writes them): every value a restart restores,
// set in turn to NaN, +-1e300, -1, 0 or an integer out of range, is refused
// (exit 2, the dataset named, the output folder left as it was) or restarts
// to a completed run with finite results. The one exception is a point put
// on the grid's edge (x_p = 0): a valid position, from which the point
// leaves the grid, and the run stops as for any point leaving it (exit 1,
// "left the grid"). Nothing crashes, hangs or stops otherwise.
#include <mpm_test_cli.hpp>
#include <mpm_test_hdf5.hpp>

#include <io/mpm_checkpoint.hpp>

#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

//! One value of a checkpoint that the sweep sets.
struct Target
{
    std::string name; //!< as the refusal names it
    bool integer;     //!< int dataset: no NaN or 1e300
    std::function<void( mpm::Checkpoint&, double )> set;
};

//! The test block with one short dynamic stage.
std::string dryText()
{
    return mpm_test::blockCaseText(
        "", "\n" + mpm_test::stageToml( "load", "dynamic", "0.06" ) +
                "snapshot_interval_s = 0.03\n" );
}

//! The saturated column with a held pore pressure, rain on its top and a
//! load on its top points: point conditions of every kind.
std::string wetText()
{
    return mpm_test::saturatedColumnCaseText(
        "wet_column",
        "\n" + mpm_test::stageToml( "rain", "dynamic", "0.004" ) +
            "snapshot_interval_s = 0.002\n" +
            mpm_test::heldBoxToml( "[[0.0, 1.75], [0.5, 2.0]]", "0.0" ) +
            mpm_test::polylineInflowToml( "[[0.0, 2.0], [0.5, 2.0]]",
                                          "1.0e-4" ) +
            "[[stages.loads]]\nwhere = \"box\"\nbox_m = [[0.0, 1.5], [0.5, "
            "2.0]]\ntraction_pa = [0.0, -1.0e3]\nlength_m = 0.5\n" );
}

//! Every value the restart restores: element 0 of each array of the state
//! and of the point conditions, and the scalar state.
std::vector<Target> targets( const mpm::Checkpoint& c )
{
    std::vector<Target> list;
    for ( std::size_t k = 0; k < c.arrays.size(); ++k )
        list.push_back( { c.arrays[k].name, c.arrays[k].integer,
                          [k]( mpm::Checkpoint& x, const double v )
                          {
                              mpm::CheckpointArray& a = x.arrays[k];
                              if ( a.integer )
                                  a.integers[0] = static_cast<int>( v );
                              else
                                  a.reals[0] = v;
                          } } );
    const auto add = [&]( const std::string& name, const bool integer,
                          const bool present,
                          std::function<void( mpm::Checkpoint&, double )> set )
    {
        if ( present )
            list.push_back( { name, integer, std::move( set ) } );
    };
    add( "conditions/load_counts", true, !c.load_counts.empty(),
         []( mpm::Checkpoint& x, double v ) { x.load_counts[0] = int( v ); } );
    add( "conditions/load_group_members", true, !c.load_groups.empty(),
         []( mpm::Checkpoint& x, double v )
         { x.load_groups[0][0] = int( v ); } );
    add( "conditions/inflow_volumes", false, !c.inflow_volumes.empty(),
         []( mpm::Checkpoint& x, double v ) { x.inflow_volumes[0] = v; } );
    add( "conditions/inflow_lengths_m", false, !c.inflow_lengths_m.empty(),
         []( mpm::Checkpoint& x, double v ) { x.inflow_lengths_m[0] = v; } );
    add( "conditions/next_surface_update_s", false, true,
         []( mpm::Checkpoint& x, double v ) { x.next_surface_update_s = v; } );
    add( "time_s", false, true,
         []( mpm::Checkpoint& x, double v ) { x.time_s = v; } );
    add( "wall_s", false, true,
         []( mpm::Checkpoint& x, double v ) { x.wall_s = v; } );
    add( "step", true, true,
         []( mpm::Checkpoint& x, double v ) { x.step = long( v ); } );
    add( "num_removed", true, true,
         []( mpm::Checkpoint& x, double v ) { x.num_removed = int( v ); } );
    add( "grid_num_active", true, true,
         []( mpm::Checkpoint& x, double v ) { x.grid_num_active = int( v ); } );
    return list;
}

struct SweepCounts
{
    int refused = 0;
    int harmless = 0;  //!< completed, finite results
    int left_grid = 0; //!< x_p on the grid's edge: the point left the grid
    int other = 0;
    std::vector<std::string> others;
};

//! Runs the sweep on `text`: a run stopped after `steps` steps, then every
//! crafted value restarted from its own copy of the checkpoint.
SweepCounts sweep( const std::string& name, const std::string& text,
                   const long steps )
{
    const fs::path dir = mpm_test::freshTempDir( "crafted_" + name );
    const fs::path file = mpm_test::writeCase( dir, text );
    const auto stopped = mpm_test::runCommand( mpm_test::runArgs(
        file, dir / "out",
        " --quiet --stop-after-steps " + std::to_string( steps ) ) );
    EXPECT_EQ( stopped.exit_code, 130 ) << stopped.output;
    const fs::path checkpoint = dir / "out" / "checkpoint.h5";
    const mpm::Checkpoint original = mpm::readCheckpoint( checkpoint.string() );
    const fs::path crafted = dir / "out" / "crafted.h5";
    const fs::path again = dir / "again";

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> reals = { nan, 1.0e300, -1.0e300, -1.0, 0.0 };
    const std::vector<double> integers = { -1.0, 0.0, double( INT_MAX ) };
    SweepCounts counts;
    for ( const Target& target : targets( original ) )
        for ( const double value : target.integer ? integers : reals )
        {
            mpm::Checkpoint c = original;
            target.set( c, value );
            mpm::writeCheckpoint( crafted.string(), c );
            fs::remove_all( again );
            const auto result = mpm_test::runCommand(
                "run " + file.string() +
                " --backend serial --quiet --restart " + crafted.string() +
                " --out " + again.string() );
            const std::string what =
                name + ": " + target.name + "[0] = " + std::to_string( value ) +
                ": exit " + std::to_string( result.exit_code );
            const bool untouched = !fs::exists( again );
            if ( result.exit_code == 2 &&
                 result.output.find( target.name ) != std::string::npos &&
                 untouched )
            {
                ++counts.refused;
                continue;
            }
            bool finite =
                result.exit_code == 0 && fs::exists( again / "particles.h5" );
            for ( const char* field : { "x", "stress" } )
                for ( const double v : mpm_test::lastSnapshotField(
                          again / "particles.h5", field ) )
                    finite = finite && std::isfinite( v );
            if ( finite )
            {
                ++counts.harmless;
                continue;
            }
            if ( target.name == "particles/x_p" && result.exit_code == 1 &&
                 result.output.find( "left the grid" ) != std::string::npos )
            {
                ++counts.left_grid;
                continue;
            }
            ++counts.other;
            counts.others.push_back( what + "\n" + result.output );
        }
    std::printf( "Crafted checkpoint values (%s): %d refused, %d harmless, "
                 "%d points put on the grid's edge left it, %d other\n",
                 name.c_str(), counts.refused, counts.harmless,
                 counts.left_grid, counts.other );
    return counts;
}

TEST( RestartCrafted, every_restored_value_is_refused_or_harmless )
{
    for ( const auto& [name, text, steps] :
          { std::tuple<std::string, std::string, long>{ "dry", dryText(), 4 },
            { "wet", wetText(), 10 } } )
    {
        const SweepCounts counts = sweep( name, text, steps );
        EXPECT_GT( counts.refused, 0 );
        EXPECT_EQ( counts.other, 0 );
        for ( const std::string& other : counts.others )
            ADD_FAILURE() << other;
    }
}

} // namespace
