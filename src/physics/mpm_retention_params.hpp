#ifndef MPM_RETENTION_PARAMS_HPP
#define MPM_RETENTION_PARAMS_HPP

namespace mpm
{
namespace physics
{
//! Soil-water retention and relative-permeability law of a material.
enum class RetentionModel : int
{
    Saturated = 0,    //!< S = 1, k_rel = 1 (no retention law evaluated)
    VanGenuchten = 1, //!< Eqs. 16-17 with Mualem's k_rel, Eq. 19
    Liakopoulos = 2,  //!< Eqs. 12-13 (corrected factor 1.9722e-11)
    Gardner = 3,      //!< S_e = exp(alpha psi), k_rel = S_e
    Linear = 4        //!< S linear in suction down to s_res, k_rel = 1
};

//---------------------------------------------------------------------------//
/*!
  \brief Parameters of a retention law, SI units. p_w is the pore-water
  pressure (compression positive); suction s = -p_w.
*/
struct RetentionParams
{
    RetentionModel model = RetentionModel::Saturated;
    double s_res = 0.0;        //!< residual degree of saturation
    double s_sat = 1.0;        //!< degree of saturation at p_w >= 0
    double alpha_per_pa = 0.0; //!< van Genuchten alpha, 1/Pa
    double n_vg = 2.0;         //!< van Genuchten n (> 1)
    double alpha_per_m = 0.0;  //!< Gardner alpha, 1/m of pressure head
    double rho_w_g = 9810.0;   //!< unit weight of water for the head, N/m^3
    //! Linear: S = s_sat - (s_sat - s_res) min(s / range, 1), s = -p_w
    double suction_range_pa = 1.0;
    double k_rel_min = 0.0; //!< floor on k_rel (Liakopoulos: e.g. 1e-4)
    //! van Genuchten: the law tabulated (RetentionTable::size values),
    //! nullptr: evaluated exactly. Owned by the simulation
    //! (RetentionTables).
    const double* table = nullptr;
};

} // namespace physics
} // namespace mpm

#endif // MPM_RETENTION_PARAMS_HPP
