#ifndef MPM_PARTICLE_VIEWS_HPP
#define MPM_PARTICLE_VIEWS_HPP

#include <mpm_device_type.hpp>

#include <Kokkos_Core.hpp>

namespace mpm
{
//---------------------------------------------------------------------------//
/*!
  \brief Material point fields, one View per field (structure of arrays).

  Naming: <quantity>_p (p = point). Vectors are (x, y); stress and strain
  are (xx, yy, xy, zz) with tensor shear components, tension positive.
*/
template <class ExecSpace, class MemoryTraits = Kokkos::MemoryManaged>
struct ParticleViews
{
    using execution_space = ExecSpace;
    using memory_space = typename ExecSpace::memory_space;
    using device_type = DeviceType<ExecSpace>;
    using scalar_view = Kokkos::View<double*, device_type, MemoryTraits>;
    using vector_view = Kokkos::View<double* [2], device_type, MemoryTraits>;
    using tensor_view = Kokkos::View<double* [4], device_type, MemoryTraits>;
    using gradient_view =
        Kokkos::View<double* [2][2], device_type, MemoryTraits>;
    using int_view = Kokkos::View<int*, device_type, MemoryTraits>;

    vector_view x_p;         //!< position, m
    vector_view x0_p;        //!< reference position for displacement, m
    vector_view v_p;         //!< velocity, m/s
    vector_view du_p;        //!< displacement increment of the step, m
    scalar_view m_p;         //!< mass, kg (per metre out of plane)
    scalar_view vol_p;       //!< current volume, m^3 (per metre)
    scalar_view vol0_p;      //!< initial volume, m^3 (per metre)
    tensor_view sigma_p;     //!< Cauchy stress, Pa
    tensor_view eps_p;       //!< accumulated (logarithmic-rate) strain, -
    scalar_view eps_p_bar_p; //!< accumulated plastic shear strain invariant
    gradient_view grad_v_p;  //!< velocity gradient L_ij = dv_i/dx_j, 1/s
    int_view material_p;     //!< material id
    int_view id_p;           //!< original index (stable identifier)
    int_view status_p;       //!< PointStatus
    int_view load_p;         //!< index of the load acting on it, -1 if none

    ParticleViews() = default;

    //! Allocates every View with num_points entries; no point carries a
    //! load.
    explicit ParticleViews( const int num_points )
    {
        allocateViews( *this, num_points );
        Kokkos::deep_copy( load_p, -1 );
    }

    using unmanaged_type = ParticleViews<ExecSpace, Kokkos::MemoryUnmanaged>;

    //! Calls f(name, pv.view...) for every View, named as the checkpoint
    //! and the point-field registry (records/mpm_point_fields.hpp) name it.
    template <class F, class... Views>
    static void forEachViewOf( F&& f, Views&... pv )
    {
        f( "x_p", pv.x_p... );
        f( "x0_p", pv.x0_p... );
        f( "v_p", pv.v_p... );
        f( "du_p", pv.du_p... );
        f( "m_p", pv.m_p... );
        f( "vol_p", pv.vol_p... );
        f( "vol0_p", pv.vol0_p... );
        f( "sigma_p", pv.sigma_p... );
        f( "eps_p", pv.eps_p... );
        f( "eps_p_bar_p", pv.eps_p_bar_p... );
        f( "grad_v_p", pv.grad_v_p... );
        f( "material_p", pv.material_p... );
        f( "id_p", pv.id_p... );
        f( "status_p", pv.status_p... );
        f( "load_p", pv.load_p... );
    }

    int size() const { return static_cast<int>( x_p.extent( 0 ) ); }
};

//! Force on one point of each load condition, N (per metre out of plane).
template <class ExecSpace>
using LoadForceView = Kokkos::View<double* [2], DeviceType<ExecSpace>>;

} // namespace mpm

#endif // MPM_PARTICLE_VIEWS_HPP
