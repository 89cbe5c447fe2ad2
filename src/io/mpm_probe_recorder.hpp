#ifndef MPM_PROBE_RECORDER_HPP
#define MPM_PROBE_RECORDER_HPP

#include <case/mpm_case_config.hpp>
#include <records/mpm_run_records.hpp>

#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Records the case's [probes] (tracked material points) every
  probes.interval_s of run time to `<out>/probes.csv`: one row per probe
  and record, header

    time_s,stage,name,point_id,x_m,y_m,u_x_m,u_y_m,v_x_m_per_s,v_y_m_per_s,
    v_w_x_m_per_s,v_w_y_m_per_s,p_w_pa,S,eps_p_bar,K_m_per_s

  Each probe follows the material point nearest to its position when the
  run starts. K_m_per_s = k rho_w g / mu (g = 9.81 m/s^2) of the point's
  material, the saturated hydraulic conductivity (0 in a dry case, whose
  water columns are "nan"). Rows go to probes.csv.partial, created
  exclusively (a planted symlink is not followed) and written per record;
  finish() renames it to probes.csv, so a crash never leaves a partial
  probes.csv behind, and a failed write (a full disk) leaves the
  .partial in place, never published.
*/
class ProbeRecorder
{
  public:
    //! Picks the probe points from the run's initial state.
    ProbeRecorder( const CaseConfig& config, const HostSnapshot& initial,
                   const std::string& out_dir );
    //! Closes probes.csv.partial if finish() was not called (it stays).
    ~ProbeRecorder();
    ProbeRecorder( const ProbeRecorder& ) = delete;
    ProbeRecorder& operator=( const ProbeRecorder& ) = delete;

    /*!
      \brief Opens probes.csv.partial. resume_time_s < 0: a new run;
      otherwise a run restarted at that run time: the rows of the earlier
      session up to it (from probes.csv or probes.csv.partial) are kept.
    */
    void open( double resume_time_s );

    bool empty() const { return _probes.empty(); }
    //! Run time of the next record (infinite without probes).
    double nextTime() const { return _next_time_s; }
    //! Appends the rows of one record and schedules the next.
    void record( const RunProgress& progress, const HostSnapshot& snapshot );
    //! Closes and renames probes.csv.partial to probes.csv, unless a
    //! write failed (then the .partial stays; failed() is true).
    void finish();
    //! True if a write to probes.csv.partial failed.
    bool failed() const { return _failed; }
    //! Path of the finished file.
    std::string path() const { return _path; }

    //! One tracked point.
    struct Probe
    {
        std::string name;
        int point = -1;          //!< index of the tracked point
        double distance_m = 0.0; //!< from the requested position at the start
    };
    const std::vector<Probe>& probes() const { return _probes; }

  private:
    std::vector<Probe> _probes;
    std::vector<double> _K_of_material;
    double _interval_s = 0.0;
    double _next_time_s = 1.0e300;
    std::string _path;
    int _fd = -1; //!< probes.csv.partial, -1 when closed
    bool _failed = false;

    //! Appends text to probes.csv.partial (failed() after an error).
    void append( const std::string& text );
};

} // namespace mpm

#endif // MPM_PROBE_RECORDER_HPP
