#ifndef MPM_SIMULATION_ERROR_HPP
#define MPM_SIMULATION_ERROR_HPP

#include <stdexcept>
#include <string>

namespace mpm
{
//! A run that cannot go on (instability, a point leaving the grid, a time
//! step above the stable limit); the message is the user-facing diagnosis.
class SimulationError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

} // namespace mpm

#endif // MPM_SIMULATION_ERROR_HPP
