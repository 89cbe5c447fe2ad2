#include <solver/drivers/mpm_fos_criterion.hpp>

#include <cmath>
#include <sstream>

namespace mpm
{
//---------------------------------------------------------------------------//
FosCriterion FosCriterion::scaled( const double factor ) const
{
    FosCriterion c = *this;
    c.displacement_limit_m *= factor;
    c.creep_limit_m *= factor;
    c.energy_ratio *= factor;
    return c;
}

//---------------------------------------------------------------------------//
void judgeTrial( const FosCriterion& criterion, FosTrialRecord& record )
{
    record.last_quarter_m = record.u_max_m - record.u_three_quarters_m;
    if ( !record.error.empty() )
    {
        record.fails = true;
        record.reason = "run_stopped";
    }
    else if ( record.u_max_m > criterion.displacement_limit_m )
    {
        record.fails = true;
        record.reason = "displacement_limit";
    }
    else if ( record.last_quarter_m > criterion.creep_limit_m &&
              record.ke_ratio > criterion.energy_ratio )
    {
        record.fails = true;
        record.reason = "still_moving";
    }
    else
    {
        record.fails = false;
        record.reason = "settled";
    }
}

//---------------------------------------------------------------------------//
MaterialConfig reducedStrength( const MaterialConfig& material,
                                const double factor )
{
    MaterialConfig m = material;
    if ( m.model != ModelType::MohrCoulomb )
        return m;
    const double deg = M_PI / 180.0;
    m.cohesion_peak_pa /= factor;
    m.cohesion_residual_pa /= factor;
    m.softening_modulus_pa /= factor;
    if ( std::isfinite( m.tensile_strength_pa ) )
        m.tensile_strength_pa /= factor;
    m.friction_angle_deg =
        std::atan( std::tan( m.friction_angle_deg * deg ) / factor ) / deg;
    m.dilation_angle_deg =
        std::atan( std::tan( m.dilation_angle_deg * deg ) / factor ) / deg;
    return m;
}

//---------------------------------------------------------------------------//
std::string describeCriterion( const FosCriterion& c )
{
    std::ostringstream s;
    s << "damped run (local damping " << c.damping << ") of " << c.periods
      << " periods of the slowest skeleton wave over the bodies (4 L / c "
         "sqrt(inertia scaling)) with c and tan(phi) divided by F and the "
         "pore pressures held (the water locked to the skeleton); fails if "
         "the largest displacement exceeds "
      << c.displacement_limit_m << " m, or if it grew by more than "
      << c.creep_limit_m
      << " m over the last quarter of the run while the mean kinetic energy "
         "of that quarter was above "
      << c.energy_ratio
      << " of the trial's peak, or if the run stops "
         "(a point leaves the grid, an instability)";
    return s.str();
}

//---------------------------------------------------------------------------//
// The record's numbers under their own names (to_json).
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE( FosTrialRecord, factor, reason, u_max_m,
                                    u_three_quarters_m, last_quarter_m,
                                    ke_ratio, duration_s, steps, wall_s )

nlohmann::json trialJson( const FosTrialRecord& r )
{
    nlohmann::json j = r;
    nlohmann::json& h = j["history"];
    for ( const FosTrialSample& s : r.history )
    {
        h["t_s"].push_back( s.t_s );
        h["u_max_m"].push_back( s.u_max_m );
        h["e_kin_j"].push_back( s.e_kin_j );
        h["moved_area_m2"].push_back( s.moved_area_m2 );
    }
    j["verdict"] = r.fails ? "fails" : "stable";
    if ( !r.error.empty() )
        j["error"] = r.error;
    return j;
}

} // namespace mpm
