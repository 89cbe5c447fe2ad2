#ifndef MPM_RETENTION_TABLES_HPP
#define MPM_RETENTION_TABLES_HPP

#include <mpm_device_type.hpp>
#include <physics/mpm_material_params.hpp>
#include <physics/mpm_retention.hpp>
#include <physics/mpm_retention_table.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//! Fills `table` (RetentionTable::size values) with the exact law `law`.
inline void fillRetentionTable( physics::RetentionParams law, double* table )
{
    law.table = nullptr; // the exact law
    law.k_rel_min = 0.0; // floored at lookup
    using physics::RetentionTable;
    for ( int i = 0; i < RetentionTable::intervals; ++i )
    {
        double f[RetentionTable::quantities][4];
        for ( int j = 0; j < 4; ++j )
        {
            const double s = RetentionTable::suction( i, j / 3.0 );
            const physics::RetentionState state =
                physics::Retention{}( law, -s );
            f[0][j] = state.S;
            f[1][j] = state.dS_dp;
            f[2][j] = state.k_rel;
        }
        for ( int q = 0; q < RetentionTable::quantities; ++q )
            RetentionTable::cubic( f[q],
                                   table + i * RetentionTable::stride + 4 * q );
    }
}

//---------------------------------------------------------------------------//
/*!
  \brief The retention tables of a simulation's materials
  (physics::RetentionTable), in the execution space's memory: `attach`
  tabulates each van Genuchten law of a material table and points the law
  at its table (solver.retention_table).
*/
template <class ExecSpace>
class RetentionTables
{
  public:
    //! Tabulates the van Genuchten laws of `materials` (others stay exact).
    void attach( physics::MaterialTable& materials )
    {
        using physics::RetentionTable;
        int count = 0;
        for ( int m = 0; m < materials.size; ++m )
            count += tabulates( materials.materials[m] );
        if ( count == 0 )
            return;
        _values = Kokkos::View<double*, DeviceType<ExecSpace>>(
            "retention_tables", count * RetentionTable::size );
        auto values_h = Kokkos::create_mirror_view( _values );
        int next = 0;
        for ( int m = 0; m < materials.size; ++m )
        {
            physics::RetentionParams& law = materials.materials[m].retention;
            if ( !tabulates( materials.materials[m] ) )
                continue;
            fillRetentionTable( law, values_h.data() + next );
            law.table = _values.data() + next;
            next += RetentionTable::size;
        }
        Kokkos::deep_copy( _values, values_h );
    }

  private:
    static bool tabulates( const physics::MaterialParams& material )
    {
        return material.retention.model ==
               physics::RetentionModel::VanGenuchten;
    }

    Kokkos::View<double*, DeviceType<ExecSpace>> _values;
};

} // namespace mpm

#endif // MPM_RETENTION_TABLES_HPP
