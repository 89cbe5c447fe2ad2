#ifndef MPM_FOS_BBAR_HPP
#define MPM_FOS_BBAR_HPP

#include <case/mpm_case_config.hpp>

namespace mpm
{
//! The trials' B-bar setting for the life of the object: the case's
//! solver.bbar if it sets it, else on; the run's setting afterwards.
class BbarForTrial
{
  public:
    BbarForTrial( SolverConfig& solver, const SolverConfig& case_solver )
        : _solver( solver )
        , _run_bbar( solver.bbar )
    {
        _solver.bbar = case_solver.bbar_given ? case_solver.bbar : true;
    }
    ~BbarForTrial() { _solver.bbar = _run_bbar; }
    BbarForTrial( const BbarForTrial& ) = delete;
    BbarForTrial& operator=( const BbarForTrial& ) = delete;

  private:
    SolverConfig& _solver;
    bool _run_bbar;
};

} // namespace mpm

#endif // MPM_FOS_BBAR_HPP
