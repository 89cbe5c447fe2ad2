#ifndef MPM_CASE_CONFIG_HPP
#define MPM_CASE_CONFIG_HPP

#include <array>
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
    double friction_angle_deg = 0.0;
    double dilation_angle_deg = 0.0;
};

//! A polygon of material (vertices in metres, either orientation).
struct BodyConfig
{
    std::string material;
    int material_id = 0; //!< index into CaseConfig::materials
    std::vector<Point2> polygon_m;
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
    Left,         //!< nodes on the grid's left edge
    Right,        //!< nodes on the grid's right edge
    Bottom,       //!< nodes on the grid's bottom edge
    Top,          //!< nodes on the grid's top edge
    BelowPolyline //!< nodes on or below a polyline y(x) (e.g. a bedrock line)
};

struct BoundaryConfig
{
    BoundarySelector where = BoundarySelector::Bottom;
    BoundaryCondition condition = BoundaryCondition::Fixed;
    //! Only for BelowPolyline: vertices with strictly increasing x, metres.
    std::vector<Point2> polyline_m;
};

enum class StageType
{
    QuasiStatic, //!< damped, runs until the kinetic-energy ratio is small
    Dynamic      //!< runs for duration_s
};

//! One analysis stage. Materials and boundaries are the effective ones of
//! this stage: the case-level definitions with this stage's overrides applied.
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
    //! Snapshot every this many seconds of stage time (0: only at stage end).
    double snapshot_interval_s = 0.0;
    //! At the end of the stage, reset displacements (x0 = x) for later stages.
    bool reset_displacement = false;
    std::vector<MaterialConfig> materials;
    std::vector<BoundaryConfig> boundaries;
};

struct GridConfig
{
    Point2 origin_m = { 0.0, 0.0 };
    double cell_size_m = 1.0;
    std::array<int, 2> cells = { 1, 1 }; //!< number of cells in x and y
};

struct SolverConfig
{
    //! Courant number: dt = courant * h / (c + |v|)_max.
    double courant_number = 0.5;
    //! Fixed time step; 0 selects the automatic (CFL) step.
    double dt_s = 0.0;
    //! FLIP fraction of the FLIP/PIC blend (1 = pure FLIP, 0 = pure PIC).
    double flip_fraction = 0.99;
    //! Cell-averaged volumetric strain rate (B-bar).
    bool bbar = false;
    //! Remove points that leave the grid (counted) instead of stopping.
    bool remove_points_leaving_grid = false;
    //! A speed above this factor times the largest wave speed is unstable.
    double instability_speed_factor = 10.0;
};

struct CaseConfig
{
    std::string file; //!< path of the case file it was read from
    std::string name;
    std::string description;
    GridConfig grid;
    int points_per_cell_per_direction = 2;
    std::vector<MaterialConfig> materials;
    std::vector<BodyConfig> bodies;
    std::vector<BoundaryConfig> boundaries;
    std::vector<StageConfig> stages;
    SolverConfig solver;
};

} // namespace mpm

#endif // MPM_CASE_CONFIG_HPP
