#ifndef MPM_SNAPSHOT_WRITER_HPP
#define MPM_SNAPSHOT_WRITER_HPP

#include <io/mpm_xdmf.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief One particle field in host memory, n_points x components,
  row-major (point-major): value (p, c) is data[p * components + c].
*/
struct FieldRef
{
    std::string name;
    const double* data;
    int components;
    std::string unit;
};

//---------------------------------------------------------------------------//
/*!
  \brief One integer particle field in host memory, n_points values.
  Stored as int32 with unit "1".
*/
struct IntFieldRef
{
    std::string name;
    const int* data;
};

//---------------------------------------------------------------------------//
/*!
  \brief Where a snapshot series stands: how many complete snapshots it
  holds and the step and time of the last one (count 0: none). A restarted
  run keeps the first `count` snapshots of the interrupted run's file, and
  checks with the step and time that the file is the series its checkpoint
  refers to.
*/
struct SnapshotSeriesMark
{
    long count = 0;
    long last_step = -1;
    double last_time_s = 0.0;
};

//---------------------------------------------------------------------------//
/*!
  \brief Crash-safe particle snapshot output (HDF5 + XDMF) that ParaView
  opens as a time series.

  HDF5 layout (format "rainslide-particles-1"):
  \code
  /                      attrs: format = "rainslide-particles-1" (string),
                                snapshot_count (int64, complete snapshots)
  /vertex_ids            int32 [n_max], 0..n_max-1: Polyvertex connectivity
  /snapshots/NNNNNN      attrs: time_s (double), stage (string),
                                stage_time_s (double), step (int64),
                                n_points (int64)
  /snapshots/NNNNNN/<f>  float64 [n] or [n x components], attr unit (string)
  /snapshots/NNNNNN/<i>  int32 [n], attr unit = "1"
  \endcode
  The field "x" (2 components, metres) holds the particle positions.

  While running, the file is `<out_dir>/<stem>.h5.partial`; it is flushed
  after each write(), so a process killed between two write() calls leaves a
  readable file whose first snapshot_count groups are complete (a kill
  during write() can leave it unreadable: HDF5 has no journal).
  finalize() renames it to `<stem>.h5` and writes `<stem>.xdmf`, a Temporal
  collection of Polyvertex grids (one vertex cell per particle, so points
  render in ParaView's XDMF and Xdmf3 readers alike). Geometry XY is "x";
  every other field is a node-centred Attribute: 1 component Scalar,
  2 or 3 Vector (ParaView's "XDMF Reader" pads 2 to 3 with z = 0, the Xdmf3
  readers keep 2), otherwise Matrix, read as one array with that many
  components (e.g. a 4-component sigma). stage_time_s and step are
  grid-centred (field data); stage is an Information element. Checked
  with ParaView 5.11. A snapshot with 0 points reads as an empty grid
  (the legacy XDMF reader also logs an error for it).

  A restarted run continues a series: the constructor given `keep_from`
  copies the first `keep.count` snapshots of that file (an interrupted
  run's `<stem>.h5` or `<stem>.h5.partial`, see findSeries) into the new
  `.h5.partial`, so the finished file holds the whole run once, without
  the interrupted run's snapshots after its checkpoint. Each snapshot group
  tracks link creation order, so copied snapshots keep their field order.

  Errors throw std::runtime_error naming the file, the object and the HDF5
  operation; invalid arguments throw std::invalid_argument.
*/
class SnapshotWriter
{
  public:
    /*!
      \brief Creates out_dir if needed and opens
      `<out_dir>/<stem>.h5.partial` (truncating any stale one).
    */
    SnapshotWriter( const std::string& out_dir,
                    const std::string& stem = "particles" );

    /*!
      \brief As above, then copies the first `keep.count` snapshots of the
      file `keep_from` (which must match `keep`, see findSeries). If
      `keep_from` is this writer's own `.h5.partial`, it is moved aside to
      `.h5.partial.resume` first and removed once copied.
    */
    SnapshotWriter( const std::string& out_dir, const std::string& stem,
                    const std::string& keep_from,
                    const SnapshotSeriesMark& keep );

    /*!
      \brief The first of `candidates` (paths of snapshot files, e.g. an
      interrupted run's `.h5.partial` then its `.h5`) that is readable, holds
      at least `keep.count` complete snapshots and whose snapshot
      `keep.count - 1` has `keep`'s step and time. Throws std::runtime_error
      saying why each candidate was refused. keep.count = 0 needs no file
      and returns "".
    */
    static std::string findSeries( const std::vector<std::string>& candidates,
                                   const SnapshotSeriesMark& keep );

    //! \brief Calls finalize() if needed; never throws.
    ~SnapshotWriter();

    SnapshotWriter( const SnapshotWriter& ) = delete;
    SnapshotWriter& operator=( const SnapshotWriter& ) = delete;

    /*!
      \brief Appends one snapshot as group /snapshots/NNNNNN and flushes the
      file (H5Fflush).

      \param time_s simulation time [s]
      \param stage name of the current stage (e.g. "gravity", "rainfall")
      \param stage_time_s time since the stage began [s]
      \param step time-step counter
      \param n_points number of particles
      \param fields double fields; must contain "x" with 2 components [m]
      \param int_fields integer fields
    */
    void write( double time_s, const std::string& stage, double stage_time_s,
                long step, int n_points, const std::vector<FieldRef>& fields,
                const std::vector<IntFieldRef>& int_fields );

    /*!
      \brief Closes the file, renames `.h5.partial` to `.h5` (std::rename)
      and writes `<stem>.xdmf` through a temporary file + rename.
      Idempotent: later calls do nothing. After a failed write() (a full
      disk) the file is closed but not published: the `.partial` stays, an
      earlier `<stem>.h5` is kept, and finalize() throws.
    */
    void finalize();

    //! \brief Final HDF5 path `<out_dir>/<stem>.h5`.
    std::string h5Path() const { return _h5_path; }

    //! \brief Final XDMF path `<out_dir>/<stem>.xdmf`.
    std::string xdmfPath() const { return _xdmf_path; }

    //! \brief Number of snapshots written so far.
    int snapshotCount() const { return static_cast<int>( _records.size() ); }

    //! \brief Count, step and time of the snapshots written so far.
    SnapshotSeriesMark mark() const;

  private:
    void preparePaths( const std::string& out_dir );
    void createFile();
    void copySnapshots( const std::string& source, long count );
    void writeVertexIds( long n_points );

    std::string _stem;
    std::string _h5_path;
    std::string _partial_path;
    std::string _xdmf_path;
    std::int64_t _file_id = -1; // hid_t of the open file
    long _vertex_id_count = 0;  // current size of /vertex_ids
    std::vector<XdmfSnapshot> _records;
    bool _finalized = false;
    bool _write_failed = false; // a write() threw: never publish the file
};

} // namespace mpm

#endif // MPM_SNAPSHOT_WRITER_HPP
