#ifndef MPM_CHECKPOINT_HPP
#define MPM_CHECKPOINT_HPP

#include <io/mpm_snapshot_writer.hpp>
#include <records/mpm_stage_state.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
//! One View of the simulation state in host memory (row-major), named
//! "<group>/<view>", e.g. "particles/x_p" or "water_grid/v_w_i".
struct CheckpointArray
{
    std::string name;
    std::vector<std::size_t> dims; //!< the View's extents
    bool integer = false;          //!< int View (values in `integers`)
    std::vector<double> reals;
    std::vector<int> integers;
};

//! What a checkpoint was written for; a restart must match the case.
struct CheckpointIdentity
{
    std::string case_name;
    std::string case_file;
    std::string case_fingerprint; //!< CaseConfig::fingerprint
    std::string analysis;         //!< "dry", "saturated" or "unsaturated"
    long num_points = 0;
    std::string backend; //!< "Serial" or "OpenMP" (informative)
    int threads = 1;     //!< (informative)
};

//---------------------------------------------------------------------------//
/*!
  \brief Everything needed to continue a run bit for bit: the simulation
  state (every View of the points and the grid, time, step count, removed
  points), the point conditions chosen at the stage start, the stage-loop
  state, and where the outputs stood.

  File layout (HDF5, format "rainslide-checkpoint-2"):
  \code
  /            attrs: format, rainslide_version, case_name, case_file,
                      case_hash (FNV-1a of the fingerprint, hex), analysis,
                      n_points, backend, threads, time_s, step,
                      num_removed, grid_num_active, wall_s,
                      snapshot_count, last_snapshot_step,
                      last_snapshot_time_s
  /case_fingerprint     uint8 [n]: CaseConfig::fingerprint text
  /state/<group>/<view> float64 or int32 [extents of the View]
  /conditions  attrs: next_surface_update_s
  /conditions/load_counts, load_group_sizes, load_group_members (int32),
              inflow_volumes, inflow_lengths_m (float64)
  /loop        attrs: json (string): the StageLoopState, finished stages
                      included, as JSON text (src/io/mpm_stage_state_json.hpp:
                      keys are the member names, non-finite doubles "nan",
                      "inf", "-inf")
  \endcode
  The root attribute attribute_digest is a checksum over every other
  attribute (AttributeDigest). Format 1 kept the loop state as one
  attribute per field; such a file is refused by its format.
*/
struct Checkpoint
{
    CheckpointIdentity identity;
    double time_s = 0.0;
    long step = 0;
    int num_removed = 0;
    int grid_num_active = 0;
    std::vector<CheckpointArray> arrays;
    // Point conditions chosen at the stage start or at the last surface
    // re-detection (StageConditions).
    std::vector<int> load_counts;
    std::vector<std::vector<int>> load_groups;
    std::vector<double> inflow_volumes;
    std::vector<double> inflow_lengths_m; //!< WaterInflow::length_m
    double next_surface_update_s = 1.0e300;
    StageLoopState loop;
    //! Snapshots written before the checkpoint (a restart keeps them).
    SnapshotSeriesMark snapshots;
    double wall_s = 0.0; //!< wall time of the run up to the checkpoint

    //! The array named `name`, or nullptr.
    const CheckpointArray* find( const std::string& name ) const;
};

//! Default checkpoint file of an output folder: `<out_dir>/checkpoint.h5`.
std::string checkpointPath( const std::string& out_dir );

/*!
  \brief Writes `checkpoint` to `path` atomically: to `<path>.partial`,
  closed and fsync'ed, then renamed over `path`, so an interruption at any
  moment leaves either the previous checkpoint or the new one.
  \throw std::runtime_error naming the file and the failed operation.
*/
void writeCheckpoint( const std::string& path, const Checkpoint& checkpoint );

//! Reads a checkpoint file. \throw std::runtime_error if it is unreadable,
//! not a checkpoint, or lacks a field.
Checkpoint readCheckpoint( const std::string& path );

/*!
  \brief Why a checkpoint cannot continue a run of the case `now`: "" if
  it can, else a message naming the checkpoint file and the case file and
  listing what differs (case name, number of points, analysis, and each
  case key whose value changed). Backend and thread count may differ.
*/
std::string checkpointMismatch( const Checkpoint& checkpoint,
                                const std::string& checkpoint_file,
                                const CheckpointIdentity& now );

} // namespace mpm

#endif // MPM_CHECKPOINT_HPP
