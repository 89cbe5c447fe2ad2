#ifndef MPM_TEST_RETENTION_HPP
#define MPM_TEST_RETENTION_HPP

#include <physics/mpm_retention_params.hpp>

namespace mpm_test
{
//! Retention parameters of `model` between the saturations s_res and s_sat.
inline mpm::physics::RetentionParams
retentionParams( const mpm::physics::RetentionModel model, const double s_res,
                 const double s_sat )
{
    mpm::physics::RetentionParams r;
    r.model = model;
    r.s_res = s_res;
    r.s_sat = s_sat;
    return r;
}

} // namespace mpm_test

#endif // MPM_TEST_RETENTION_HPP
