#ifndef MPM_XDMF_HPP
#define MPM_XDMF_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace mpm
{
//! What the XDMF file says of one field of a snapshot.
struct XdmfField
{
    std::string name;
    int components;
    bool is_int;
};

//! What the XDMF file says of one snapshot of particles.h5.
struct XdmfSnapshot
{
    double time_s;
    std::string stage;
    double stage_time_s;
    long step;
    long n_points;
    std::vector<XdmfField> fields;
};

/*!
  \brief The XDMF text of a snapshot series stored as `<stem>.h5` (next to
  the XDMF file), as SnapshotWriter describes it: a Temporal collection of
  Polyvertex grids, one per snapshot, with /vertex_ids of
  `vertex_id_count` entries; "x" is the Geometry, every other field a
  node-centred Attribute.
*/
std::string xdmfText( const std::string& stem,
                      const std::vector<XdmfSnapshot>& snapshots,
                      long vertex_id_count );

//! Name of snapshot group `index` of particles.h5: "NNNNNN".
std::string snapshotGroupName( std::size_t index );

//! Shortest decimal text that reads back as the same double.
std::string formatDouble( double value );

} // namespace mpm

#endif // MPM_XDMF_HPP
