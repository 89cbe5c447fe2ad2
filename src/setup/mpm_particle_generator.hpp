#ifndef MPM_PARTICLE_GENERATOR_HPP
#define MPM_PARTICLE_GENERATOR_HPP

#include <case/mpm_case_config.hpp>

#include <vector>

namespace mpm
{
//! Initial material points in host memory (structure of arrays).
struct InitialPoints
{
    std::vector<double> x;   //!< 2 per point, m
    std::vector<double> vol; //!< m^3 per metre out of plane
    std::vector<int> material;
    std::vector<int> body; //!< index into CaseConfig::bodies
    int size() const { return static_cast<int>( vol.size() ); }
};

/*!
  \brief Material points of every body: n x n points per grid cell at the
  Gauss positions of the cell, volume h^2 / n^2, kept where the point lies
  inside the body's polygon (the first body that contains a point owns it),
  in the order of the cells' columns (x-major, as the nodes' flat index),
  so that threads splitting the points and the nodes share little.
*/
InitialPoints generatePoints( const CaseConfig& config );

//! Node flag mask (NodeFlag) of every node, flat index i * (ny + 1) + j.
std::vector<int> nodeFlags( const GridConfig& grid,
                            const std::vector<BoundaryConfig>& boundaries );

/*!
  \brief The interior walls (where = "polyline") of `boundaries` if `walls`,
  else the other boundaries, in their order.
*/
std::vector<BoundaryConfig>
interiorWalls( const std::vector<BoundaryConfig>& boundaries, bool walls );

} // namespace mpm

#endif // MPM_PARTICLE_GENERATOR_HPP
