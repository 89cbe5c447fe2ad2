#ifndef MPM_POINT_FIELDS_HPP
#define MPM_POINT_FIELDS_HPP

#include <records/mpm_run_records.hpp>

#include <cstring>
#include <vector>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief The point fields of the output, declared once: their name in
  particles.h5 (and the probes' and scripts' vocabulary), their name in
  messages, unit, components,
  the HostSnapshot member that holds them and the View they copy (its name
  in ParticleViews / WaterParticleViews::forEachViewOf; null for a derived
  field) and its columns in probes.csv (null if not probed). hostSnapshot
  fills the members from the Views, writeSnapshot writes them, the probe
  recorder writes the probed ones, the diagnosis of an unstable point
  (solver/mpm_diagnosis.hpp) prints and checks them, the test PointFields.*
  checks the names against the Views.
*/
struct PointField
{
    const char* name;  //!< in particles.h5
    const char* label; //!< in messages (the diagnosis of a point)
    const char* unit;
    int components;
    std::vector<double> HostSnapshot::*values;
    const char* view; //!< the View copied, null if derived
    bool two_phase;   //!< only in two-phase scenes
    //! Its probes.csv columns, one per component, comma-separated.
    const char* probe_columns;
};

//! An integer point field (unit "1").
struct IntPointField
{
    const char* name;
    std::vector<int> HostSnapshot::*values;
    const char* view;
};

//! The double fields, in the order particles.h5 stores them.
inline const std::vector<PointField>& pointFields()
{
    using H = HostSnapshot;
    static const std::vector<PointField> fields = {
        { "x", "position", "m", 2, &H::x, "x_p", false, "x_m,y_m" },
        { "displacement", "displacement", "m", 2, &H::displacement, nullptr,
          false, "u_x_m,u_y_m" },
        { "velocity", "velocity", "m/s", 2, &H::v, "v_p", false,
          "v_x_m_per_s,v_y_m_per_s" },
        { "stress", "stress", "Pa", 4, &H::sigma, "sigma_p", false, nullptr },
        { "strain", "strain", "-", 4, &H::eps, "eps_p", false, nullptr },
        { "plastic_shear_strain", "plastic shear strain (eps_p_bar)", "-", 1,
          &H::eps_p_bar, "eps_p_bar_p", false, "eps_p_bar" },
        { "volume", "volume", "m^3/m", 1, &H::vol, "vol_p", false, nullptr },
        { "mass", "mass", "kg/m", 1, &H::mass, "m_p", false, nullptr },
        { "pore_pressure", "pore pressure", "Pa", 1, &H::p_w, "p_w_p", true,
          "p_w_pa" },
        { "saturation", "saturation", "-", 1, &H::S, "S_p", true, "S" },
        { "porosity", "porosity", "-", 1, &H::n, "n_p", true, nullptr },
        { "water_velocity", "water velocity", "m/s", 2, &H::v_w, "v_w_p", true,
          "v_w_x_m_per_s,v_w_y_m_per_s" },
        { "relative_permeability", "relative permeability", "-", 1, &H::k_rel,
          "k_rel_p", true, nullptr } };
    return fields;
}

//! The integer fields, in the order particles.h5 stores them.
inline const std::vector<IntPointField>& intPointFields()
{
    using H = HostSnapshot;
    static const std::vector<IntPointField> fields = {
        { "material", &H::material, "material_p" },
        { "id", &H::id, "id_p" },
        { "status", &H::status, "status_p" } };
    return fields;
}

//! The HostSnapshot member that holds a copy of View `view`, or null.
template <class T>
std::vector<T> HostSnapshot::*snapshotMemberOf( const char* view );

template <>
inline std::vector<double> HostSnapshot::*
snapshotMemberOf<double>( const char* view )
{
    for ( const PointField& f : pointFields() )
        if ( f.view && std::strcmp( f.view, view ) == 0 )
            return f.values;
    return nullptr;
}

template <>
inline std::vector<int> HostSnapshot::*snapshotMemberOf<int>( const char* view )
{
    for ( const IntPointField& f : intPointFields() )
        if ( std::strcmp( f.view, view ) == 0 )
            return f.values;
    return nullptr;
}

} // namespace mpm

#endif // MPM_POINT_FIELDS_HPP
