#ifndef MPM_CASE_CONFIG_HPP
#define MPM_CASE_CONFIG_HPP

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
// Plain data describing one simulation case, as read from a TOML case file.
// All quantities are SI; the unit is part of each member name.
// Stress is tension positive; gravity points along -y by default.
//---------------------------------------------------------------------------//

using Point2 = std::array<double, 2>;

enum class ModelType
{
    LinearElastic,
    MohrCoulomb
};

//! The plastic strain the cohesion softens on (physics::SofteningMeasure).
enum class SofteningMeasureType
{
    EquivalentPlasticStrain, //!< sum sqrt( 2/3 de_p : de_p ), the paper's
    EngineeringShearStrain   //!< sum ( de_1 - de_3 )^p
};

//! Which phases a scene models (kernels and fields of the others are
//! neither run nor allocated).
enum class AnalysisType
{
    Dry,        //!< single phase, total stress (bulk density)
    Saturated,  //!< solid + water, S = 1, no retention law
    Unsaturated //!< solid + water with a retention law
};

//! Soil-water retention / relative permeability law.
enum class RetentionType
{
    Saturated,    //!< S = 1, k_rel = 1
    VanGenuchten, //!< Eqs. 16-17 with Mualem k_rel (Eq. 19)
    Liakopoulos,  //!< Eqs. 12-13 (corrected factor 1.9722e-11 Pa^-2.4279)
    Gardner,      //!< S_e = exp(alpha psi), k_rel = S_e
    Linear        //!< S linear in suction down to S_res, k_rel = 1
};

struct RetentionConfig
{
    RetentionType model = RetentionType::Saturated;
    double residual_saturation = 0.0;
    double saturated_saturation = 1.0;
    double alpha_per_pa = 0.0;     //!< van Genuchten alpha
    double n = 2.0;                //!< van Genuchten n
    double alpha_per_m = 0.0;      //!< Gardner alpha (per metre of head)
    double suction_range_pa = 1.0; //!< Linear: suction where S reaches S_res
    double k_rel_min = 0.0;        //!< floor on k_rel
};

//! Constitutive parameters of one named material.
struct MaterialConfig
{
    std::string name;
    ModelType model = ModelType::LinearElastic;
    //! Bulk density of the material point (solid + pore content), kg/m^3.
    double density_kg_per_m3 = 0.0;
    double youngs_modulus_pa = 0.0;
    double poisson_ratio = 0.0;
    // Mohr–Coulomb with linear cohesion softening (Eqs. 14–15).
    double cohesion_peak_pa = 0.0;
    double cohesion_residual_pa = 0.0;
    //! dc/d(eps_p_bar), negative for softening, Pa.
    double softening_modulus_pa = 0.0;
    SofteningMeasureType softening_measure =
        SofteningMeasureType::EquivalentPlasticStrain;
    double friction_angle_deg = 0.0;
    double dilation_angle_deg = 0.0;
    //! Tension cut-off sigma_t0 (peak; softens with c), Pa; +infinity: none.
    double tensile_strength_pa = std::numeric_limits<double>::infinity();
    // Two-phase scenes only (Saturated / Unsaturated).
    double solid_density_kg_per_m3 = 0.0; //!< grain density rho_s
    double porosity = 0.0;                //!< initial porosity n0
    double permeability_m2 = 0.0;         //!< intrinsic permeability k
    RetentionConfig retention;
};

//! Properties of the pore water (two-phase scenes).
struct WaterConfig
{
    double density_kg_per_m3 = 1000.0;
    double bulk_modulus_pa = 2.2e9;
    double viscosity_pa_s = 1.0e-3;
};

//! Piecewise-linear function of stage time: (t_s, value) pairs; constant
//! beyond the ends; empty means 1.
using TimeFunction = std::vector<std::array<double, 2>>;

//! How the length of an inflow polyline is measured.
enum class LineMeasure
{
    AlongLine, //!< the length along the line (flux per unit line length)
    Horizontal //!< its horizontal projection (rain measured on the level)
};

//! Selects material points by their position at the stage start.
struct PointSelection
{
    enum class Kind
    {
        Box,           //!< points inside box_m = [[x0, y0], [x1, y1]]
        SurfaceCells,  //!< points initially in cells below an empty cell
        TopCells,      //!< points in the cells along the grid's top edge
        BottomCells,   //!< ... its bottom edge
        LeftCells,     //!< ... its left edge
        RightCells,    //!< ... its right edge
        All,           //!< every active point
        SurfacePoints, //!< the two highest points of each column of points
        Polyline       //!< points of the cells polyline_m passes through
    };
    Kind kind = Kind::Box;
    std::array<Point2, 2> box_m = { Point2{ 0.0, 0.0 }, Point2{ 0.0, 0.0 } };
    //! Polyline only: its vertices (m) and how its length is measured
    //! (a cell the line crosses only vertically has no horizontal length).
    std::vector<Point2> polyline_m;
    LineMeasure polyline_measure = LineMeasure::AlongLine;
};

/*!
  Prescribed water inflow (rainfall of intensity flux_m_per_s, times f(t)).
  On points (box, surface_cells; a surface of length length_m): the water
  volume flux * length * dt of a step is added to the selected points in
  proportion to their volume (a mass-conservative source in Eq. 8). On a
  grid edge (top, bottom, left, right): a flux boundary of the water, the
  edge nodes' water moving into the soil relative to the solid at
  flux / (n S) (an impermeable edge with a prescribed seepage; the length
  is the edge's). With ponding, a selected point (on an edge: a point of
  the edge's cells) that saturates keeps p_w <= 0 (the excess runs off).
  On a polyline: length_m is the polyline's length (along it or projected
  on the horizontal), and each cell it passes through takes the water of
  its piece of the line (polylineCellShares).
*/
struct WaterInflow
{
    PointSelection points;
    double flux_m_per_s = 0.0;
    double length_m = 1.0;
    TimeFunction time_function;
    bool ponding = true;
    //! > 0: the fed points are the current surface cells, re-detected
    //! every this many seconds, and length_m is the surface's current
    //! horizontal projection (rain falls vertically); 0: fixed selection.
    double follow_surface_interval_s = 0.0;

    //! True for a flux boundary on a grid edge (no point source).
    bool onGridEdge() const
    {
        using Kind = PointSelection::Kind;
        return points.kind == Kind::TopCells ||
               points.kind == Kind::BottomCells ||
               points.kind == Kind::LeftCells ||
               points.kind == Kind::RightCells;
    }
};

//! Prescribed pore pressure on selected points: p_w = pressure_pa * f(t),
//! or, with hold_initial, each point's p_w at the stage start.
struct PorePressureCondition
{
    PointSelection points;
    double pressure_pa = 0.0;
    TimeFunction time_function;
    //! Hold each selected point's p_w at its value at the stage start
    //! (pressure_pa and time_function are not used).
    bool hold_initial = false;
};

//! External force on selected points: traction_pa * length_m shared
//! equally by the selected points, times f(t). A point selected by several
//! loads carries their sum.
struct PointLoad
{
    PointSelection points;
    Point2 traction_pa = { 0.0, 0.0 };
    double length_m = 1.0;
    TimeFunction time_function;
};

//! A polygon of material (vertices in metres, either orientation).
struct BodyConfig
{
    std::string material;
    int material_id = 0; //!< index into CaseConfig::materials
    std::vector<Point2> polygon_m;
    //! Two-phase: initial pore pressure p_w = a + b * y (Pa, y in m).
    double initial_pore_pressure_pa = 0.0;
    double initial_pore_pressure_gradient_pa_per_m = 0.0;
    //! Two-phase, instead of a + b y: (y_m, p_w_pa) pairs, y increasing;
    //! p_w piecewise linear in y, constant beyond the ends. Empty: a + b y.
    std::vector<std::array<double, 2>> initial_pore_pressure_profile;
};

//! What a boundary condition prescribes on the selected nodes.
enum class BoundaryCondition
{
    Fixed, //!< v_x = v_y = 0
    FixX,  //!< v_x = 0 (a roller on a vertical wall)
    FixY   //!< v_y = 0 (a roller on a horizontal floor)
};

//! Which grid nodes a boundary condition applies to.
enum class BoundarySelector
{
    Left,          //!< nodes on the grid's left edge
    Right,         //!< nodes on the grid's right edge
    Bottom,        //!< nodes on the grid's bottom edge
    Top,           //!< nodes on the grid's top edge
    BelowPolyline, //!< nodes on or below a polyline y(x) (e.g. a bedrock line)
    //! An interior wall or gate along a polyline in any direction: the
    //! nodes whose shape function is not zero somewhere on it (wallNodes).
    Polyline
};

//! What a boundary prescribes for the pore water (two-phase scenes).
enum class HydraulicCondition
{
    Impermeable, //!< water normal velocity = solid normal velocity (default)
    Drained      //!< water leaves/enters freely (p_w = 0 in the weak sense)
};

struct BoundaryConfig
{
    BoundarySelector where = BoundarySelector::Bottom;
    BoundaryCondition condition = BoundaryCondition::Fixed;
    //! Only for two-phase scenes; grid edges are impermeable by default.
    //! An impermeable Polyline ties the water to the solid on its nodes;
    //! a drained one lets the water through (it changes no water tie).
    HydraulicCondition hydraulic = HydraulicCondition::Impermeable;
    //! False for a purely hydraulic boundary (no solid constraint).
    bool constrains_solid = true;
    //! BelowPolyline: vertices with strictly increasing x, metres.
    //! Polyline: the wall's vertices (>= 2, consecutive ones distinct,
    //! inside the grid), metres. Unused by the other selectors.
    std::vector<Point2> polyline_m;
};

//! The boundaries of a soil box: rollers on the left and right grid edges
//! (x fixed), the base fixed.
inline std::vector<BoundaryConfig> rollerSidesFixedBase()
{
    BoundaryConfig left, right, bottom;
    left.where = BoundarySelector::Left;
    left.condition = BoundaryCondition::FixX;
    right.where = BoundarySelector::Right;
    right.condition = BoundaryCondition::FixX;
    bottom.where = BoundarySelector::Bottom;
    bottom.condition = BoundaryCondition::Fixed;
    return { left, right, bottom };
}

enum class StageType
{
    QuasiStatic, //!< damped, runs until the kinetic-energy ratio is small
    Dynamic      //!< runs for duration_s
};

//! One analysis stage. Materials and boundaries are the effective ones of
//! this stage: the case-level definitions with this stage's overrides applied.
/*!
  \brief Ends a dynamic stage once the bodies are static again: after a
  slide (a point has moved farther than slide_displacement_m from its
  reference position), the speed_percentile-th percentile of the active
  points' speeds (100: every point) has stayed below static_speed_m_per_s
  for window_s. A stage without a slide runs for its duration.
*/
struct StaticStop
{
    double static_speed_m_per_s = 0.0; //!< 0: no static stop
    double slide_displacement_m = 0.5;
    double window_s = 1.0;
    //! Percentile p in (0, 100] of the point speeds that must stay below
    //! the static speed (nearest rank: at most floor(N (100 - p) / 100) of
    //! the N active points as fast or faster); 100 = the largest speed.
    double speed_percentile = 100.0;
    bool enabled() const { return static_speed_m_per_s > 0.0; }
};

struct StageConfig
{
    std::string name;
    StageType type = StageType::Dynamic;
    Point2 gravity_m_per_s2 = { 0.0, -9.81 };
    //! Local (non-viscous) damping coefficient, 0 <= damping < 1.
    double damping = 0.0;
    //! Dynamic: simulated duration. Quasi-static: upper limit of the stage.
    double duration_s = 0.0;
    //! Quasi-static: stop when E_kin / max(E_kin over the stage) < this.
    double ke_ratio_tolerance = 1.0e-4;
    //! Dynamic: optional stop once the bodies are static again.
    StaticStop static_stop;
    //! Snapshot every this many seconds of stage time (0: only at stage end).
    double snapshot_interval_s = 0.0;
    //! Further snapshots at these stage times (s, increasing); steps are
    //! shortened to land on them.
    std::vector<double> snapshot_times_s;
    //! At the end of the stage, reset displacements (x0 = x) for later stages.
    bool reset_displacement = false;
    //! At the stage start, set the geostatic stress with this earth pressure
    //! coefficient K0 (sigma_h = K0 sigma_v; mpm_initial_stress.hpp);
    //! 0: none (the stress is what the earlier stages left).
    double initial_stress_k0 = 0.0;
    std::vector<MaterialConfig> materials;
    std::vector<BoundaryConfig> boundaries;
    //! Prescribed point pore pressures active in this stage.
    std::vector<PorePressureCondition> pore_pressures;
    //! Loads active in this stage.
    std::vector<PointLoad> loads;
    //! Water inflows (rainfall) active in this stage.
    std::vector<WaterInflow> inflows;
};

struct GridConfig
{
    Point2 origin_m = { 0.0, 0.0 };
    double cell_size_m = 1.0;
    std::array<int, 2> cells = { 1, 1 }; //!< number of cells in x and y
};

//! How a two-phase step finds the pore pressure (solver.scheme).
enum class TwoPhaseScheme
{
    Explicit,     //!< Eq. 8 at the points (docs/formulation.md §3)
    SemiImplicit, //!< a cell pressure solve (docs/formulation.md §9)
    Seepage,      //!< the skeleton held, the flow in real time (§10)
    QuasiStatic,  //!< the flow in real time, the skeleton relaxed (§11)
    Auto //!< quasi-static in equilibrium, semi-implicit in motion (§12)
};

struct SolverConfig
{
    //! Courant number: dt = courant * h / (c + |v|)_max.
    double courant_number = 0.5;
    //! Fixed time step; 0 selects the automatic (CFL) step.
    double dt_s = 0.0;
    //! FLIP fraction of the FLIP/PIC blend (1 = pure FLIP, 0 = pure PIC) at
    //! a step of the explicit scheme's CFL limit; smaller steps blend
    //! proportionally less PIC, the semi-implicit scheme's longer ones more
    //! (physics::stepFlipFraction).
    double flip_fraction = 0.99;
    //! Two-phase: the water takes the solid's FLIP/PIC update plus its
    //! seepage velocity, damped as the drag damps it but never faster than
    //! the PIC share (mpm::twoPhaseBlend, physics::seepageMemory).
    bool water_relative_flip = true;
    //! Cell-averaged volumetric strain rate (B-bar).
    bool bbar = false;
    //! solver.bbar is set in the case file; if not, the trials of
    //! `rainslide fos` use B-bar (FosTrialRunner).
    bool bbar_given = false;
    /*!
      A point dilated to J = V / V0 > 1 has the moduli K / J and G / J, so
      its P-wave speed, and the stable step, do not grow as it stretches
      (physics::MaterialParams::moduli_fall_with_dilation).
    */
    bool moduli_fall_with_dilation = true;
    /*!
      Complete the stress divergence of cells cut by a fixed base (a base
      line between grid lines): physics::BaseCellCompletion.
    */
    bool base_cell_completion = true;
    //! Two-phase: the points of a cell share one p_w that holds their
    //! water (physics::CellWaterEquilibrium).
    bool cell_equilibrium = true;
    //! ... with a pressure varying linearly across the cell, its slope
    //! limited from the neighbours' (physics::limitedPressureSlope).
    bool cell_pressure_slope = true;
    //! Unsaturated: van Genuchten laws evaluated from a table
    //! (physics::RetentionTable: <= 1.2e-7 relative), not exactly.
    bool retention_table = true;
    //! Remove points that leave the grid (counted) instead of stopping.
    bool remove_points_leaving_grid = false;
    //! A speed above this factor times the largest wave speed is unstable.
    double instability_speed_factor = 10.0;
    /*!
      Inertia (mass) scaling f >= 1 for slow, quasi-static processes: the
      inertial masses of the momentum balance are multiplied by f (the
      weights are not), which slows the waves by sqrt(f) and allows a step
      sqrt(f) times larger. 1 = true dynamics.
    */
    double inertia_scaling = 1.0;
    //! Simulated time between checkpoints (restart files); 0 = none.
    double checkpoint_interval_s = 0.0;
    //! Two-phase: explicit Eq. 8, the semi-implicit pressure solve,
    //! seepage through the held skeleton, the quasi-static scheme, or auto.
    TwoPhaseScheme scheme = TwoPhaseScheme::Explicit;
    //! Seepage: the largest change of a point's saturation in one step
    //! that sets the next step.
    double seepage_saturation_change = 0.01;
    //! Seepage and quasi-static: the first step of every stage, s.
    double seepage_initial_dt_s = 0.01;
    //! Quasi-static: the skeleton is at rest once its fastest point moves
    //! slower than this, m/s.
    double relaxation_speed_m_per_s = 1.0e-6;
    //! Quasi-static: the most damped steps of one relaxation.
    double relaxation_max_steps = 20000;
    //! Quasi-static: the relaxation's least local damping coefficient.
    double relaxation_damping = 0.7;
    //! Auto: the bodies are at rest again once the fastest point has
    //! stayed slower than this, m/s ...
    double auto_rest_speed_m_per_s = 1.0e-3;
    //! ... for this long, s.
    double auto_rest_window_s = 1.0;
    //! Semi-implicit: the pressure solve stops at |r| <= tolerance |b|.
    double pressure_tolerance = 1.0e-10;
    //! Semi-implicit: the most conjugate-gradient iterations of one solve.
    double pressure_max_iterations = 2000.0;
    //! Semi-implicit: modified Picard stops at a water residual |R| <= this
    //! |b| (b the step's predicted water volume rates at the nodes).
    double pressure_picard_tolerance = 1.0e-4;
};

//! A tracked material point: the one nearest to position_m when the run
//! starts; its fields are recorded in probes.csv.
struct ProbeConfig
{
    std::string name;
    Point2 position_m{ 0.0, 0.0 };
};

//! [probes]: tracked points and how often they are recorded.
struct ProbesConfig
{
    double interval_s = 0.0; //!< simulated time between records
    std::vector<ProbeConfig> points;
};

struct CaseConfig
{
    std::string file; //!< path of the case file it was read from
    //! Canonical text of the case's keys (caseFingerprint); identifies the
    //! case of a checkpoint. Empty for cases built in code.
    std::string fingerprint;
    //! `--set KEY=VALUE` overrides applied to the file (readCaseFile).
    std::vector<std::string> overrides;
    //! Warnings of the reader ("file:line:column: warning: ..."), in file
    //! order; the case is valid, the CLI prints them at check and run.
    std::vector<std::string> warnings;
    std::string name;
    std::string description;
    AnalysisType analysis = AnalysisType::Dry;
    WaterConfig water;
    GridConfig grid;
    int points_per_cell_per_direction = 2;
    std::vector<MaterialConfig> materials;
    std::vector<BodyConfig> bodies;
    std::vector<BoundaryConfig> boundaries;
    std::vector<StageConfig> stages;
    SolverConfig solver;
    ProbesConfig probes;
};

} // namespace mpm

#endif // MPM_CASE_CONFIG_HPP
