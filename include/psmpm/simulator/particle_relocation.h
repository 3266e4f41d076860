// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_particle_relocation_h
#define psmpm_simulator_particle_relocation_h

#include <psmpm/simulator/stability_monitor.h>
#include <psmpm/simulator/state.h>

#include <cstdint>
#include <map>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * After the particles have moved: their cells, the basis at their new
     * positions, and the particles that moved to cells of another rank
     * sent there. A step's relocation is begin(), locate() on every
     * particle in ranges from the first (a transfer scheme does it chunk
     * by chunk while the moved particles are in the cache,
     * TransferScheme::move_and_update_material(); else the simulator in
     * one range), then finish() on every rank (collective).
     */
    template <int dim>
    class ParticleRelocation
    {
    public:
      /// A step's relocation starts: the basis arrays are sized for the
      /// particles there are.
      void
      begin(State<dim> &state);

      /// The cells of particles [@p first, @p last) and the basis there;
      /// those that left this rank's cells are packed for their owners
      /// (and keep their basis until finish()). A particle that left the
      /// mesh is reported and keeps its cell (the run stops after this
      /// step). Returns how many of the range left this rank.
      std::size_t
      locate(State<dim>       &state,
             StabilityMonitor &monitor,
             const std::size_t first,
             const std::size_t last);

      /// Whether particle @p p left this rank in locate().
      bool
      leaving(const std::size_t p) const
      {
        return any_leaving && !keep[p];
      }

      /// Ship the particles that left and receive those that came
      /// (collective), locate the received ones and evaluate the basis
      /// there. Returns the index of the first received particle; the
      /// ones before it were located by locate() and kept their order.
      std::size_t
      finish(State<dim> &state);

      /// Particles the last finish() sent to other ranks.
      std::size_t
      particles_sent() const
      {
        return sent;
      }

      /// Particles that changed cells on this rank since construction.
      std::uint64_t
      cell_crossings() const
      {
        return crossings;
      }

    private:
      std::map<unsigned int, std::vector<double>> outgoing;
      std::vector<bool>                           keep;
      bool                                        any_leaving = false;
      std::uint64_t                               crossings   = 0;
      std::size_t                                 sent        = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
