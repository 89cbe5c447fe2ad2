#ifndef MPM_FAILURE_VERDICT_HPP
#define MPM_FAILURE_VERDICT_HPP

#include <records/mpm_run_records.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mpm
{
//! Thresholds of the failure verdict (the definitions in FailureVerdict).
struct VerdictThresholds
{
    double disp_threshold_m = 0.1;
    double eps_threshold = 0.05;
    double moved_threshold_m = 0.5;
    double link_factor = 1.5;
    double min_group_area_m2 = 1.0;
    double jump_rate_m2_per_s = 4.0;
    double quiet_s = 1.0;
};

//! One onset of sliding: the first failure or a later slide.
struct SlideOnset
{
    double time_s = 0.0;       //!< run time of the snapshot
    double stage_time_s = 0.0; //!< time since its stage started
    std::string stage;
    std::string reason; //!< "first failure", "detached group", "area jump"
    double new_area_m2 = 0.0; //!< area newly entering counted groups
    double sliding_area_m2 = 0.0;
    //! Where the new sliding points were at the stage start: centroid and
    //! horizontal extent, m.
    double x_m = 0.0, y_m = 0.0, x_min_m = 0.0, x_max_m = 0.0;
};

/*!
  \brief Whether and how a run failed, from its snapshots (run in the
  output observer, so every `rainslide run` ends with one).

  Only the snapshots of the stages marked `analysed` (the dynamic ones)
  count. Definitions, shared with scripts/slope_metrics.py:
  - reference state: the positions at the start of the snapshot's stage
    (the snapshot that ended the previous stage; for the first stage, or
    the first stage seen after a restart, x - displacement);
  - sliding point: active, with |x - x_ref| > disp_threshold_m and
    plastic shear strain > eps_threshold, or |x - x_ref| > moved_threshold_m;
  - sliding group: sliding points linked by chains of neighbours closer
    than link_factor x the initial point spacing (the square root of the
    median point volume of the first snapshot); counted if its area is at
    least min_group_area_m2;
  - first failure: the first snapshot with a counted group;
  - later slide: a counted group not linked to any point counted at an
    earlier snapshot ("detached group"), or the area newly entering counted
    groups growing at jump_rate_m2_per_s or more after a quiet spell ("area
    jump": re-armed once the rate stayed below half of it for quiet_s; the
    first failure arms it the same way);
  - run-out: how far the sliding mass reaches beyond the ground at the
    stage start: the largest horizontal distance, in the direction of its
    mean horizontal motion, from a point of a counted group to the farthest
    reference point in the same band of height (bands one point spacing
    high), or 0 while it stays within the initial outline, m;
  - largest displacement: the largest |x - x_ref| of an active point.
*/
class FailureVerdict
{
  public:
    FailureVerdict( std::vector<bool> analysed_stages,
                    VerdictThresholds thresholds = VerdictThresholds() );

    //! Takes in a snapshot.
    void add( const RunProgress& progress, const HostSnapshot& snapshot );
    //! The stage `progress.stage_index` ended in `end_state`: the next
    //! stage's reference state.
    void endStage( const RunProgress& progress, const HostSnapshot& end_state );

    bool failed() const { return !_onsets.empty(); }
    const std::vector<SlideOnset>& onsets() const { return _onsets; }
    double slidingAreaM2() const { return _sliding_area_m2; }
    double runOutM() const { return _run_out_m; }
    double maxDisplacementM() const { return _max_displacement_m; }
    int snapshotsAnalysed() const { return _snapshots_analysed; }

    //! metrics.json's `verdict`; `case_file` names the case in the pointer
    //! to `rainslide fos` of a run that did not fail.
    nlohmann::json json( const std::string& case_file ) const;
    //! One line: "FAILED: ..." or "no failure: ...".
    std::string line( const std::string& case_file ) const;

  private:
    void setReference( const HostSnapshot& snapshot, bool from_displacement );
    void analyse( const RunProgress& progress, const HostSnapshot& snapshot );
    //! The band of height of `y` for the outline (one point spacing high).
    long long heightBand( double y ) const;

    std::vector<bool> _analysed;
    VerdictThresholds _thresholds;
    double _spacing_m = 0.0;
    int _reference_stage = -1;
    std::vector<int> _ref_index; //!< point id -> reference slot, or -1
    std::vector<double> _ref_x;  //!< reference positions, 2 per slot
    std::vector<char> _ever;     //!< per point id: in a counted group before
    //! Per band of height (key: floor(y / spacing)): the smallest and the
    //! largest x of the reference state.
    std::unordered_map<long long, std::pair<double, double>> _outline;
    double _prev_time_s = 0.0; //!< of the previous analysed snapshot
    bool _armed = true;
    double _last_high_s = 0.0;
    int _snapshots_analysed = 0;
    double _first_time_s = -1.0; //!< of the first analysed snapshot
    double _last_time_s = 0.0;
    std::vector<SlideOnset> _onsets;
    double _sliding_area_m2 = 0.0;
    double _run_out_m = 0.0;
    double _max_displacement_m = 0.0;
    double _max_displacement_time_s = 0.0;
    double _max_displacement_x_m = 0.0, _max_displacement_y_m = 0.0;
};

//! Labels 0..G-1 of the groups of points `xy` (2 per point) linked by
//! chains of neighbours closer than `link_m`.
std::vector<int> linkedGroups( const std::vector<double>& xy, double link_m );

} // namespace mpm

#endif // MPM_FAILURE_VERDICT_HPP
