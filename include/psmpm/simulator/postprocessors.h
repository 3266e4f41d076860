// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_postprocessors_h
#define psmpm_simulator_postprocessors_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/postprocess/postprocessor.h>
#include <psmpm/simulator/state.h>
#include <psmpm/simulator/transfer_scheme.h>

#include <memory>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Simulator
  {
    using namespace dealii;

    /**
     * Every registered postprocessor (Postprocess::PostprocessorRegistry),
     * in their order(), and the simulator's one call per hook into them
     * all. Also the transfer scheme's UpdatedChunkObserver, which hands
     * the updated chunks to the postprocessors that observe them.
     */
    template <int dim>
    class Postprocessors : public UpdatedChunkObserver<dim>
    {
    public:
      /// The entries of every postprocessor of either dimension.
      static void
      declare_parameters(ParameterHandler &prm);

      /// Create every postprocessor and let each read its entries.
      void
      parse_parameters(ParameterHandler &prm);

      /// The hooks of Postprocess::Postprocessor, in order.
      void
      check_mesh(const Mesh::CellLocator<dim> &locator, MPI_Comm comm) const;
      void
      initialize(const Postprocess::StateView<dim> &view);
      void
      start(const Postprocess::StateView<dim> &view);
      void
      execute(const Postprocess::StateView<dim> &view,
              Postprocess::StatisticsTable      &statistics);
      void
      write(const Postprocess::StateView<dim> &view);
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);
      void
      fill_summary(const Postprocess::StateView<dim> &view,
                   Summary              &summary) const;

      /// The energies of the last execute() (zero if no postprocessor
      /// computes them).
      Postprocess::EnergyBalance
      energy_balance() const;

      /// Whether any postprocessor observes the updated chunks.
      bool
      observes_updated_chunks() const
      {
        return !observers.empty();
      }

      /// To the observing postprocessors, with the reference of the last
      /// initialize() (the view's output directory is empty here: no
      /// file is written per chunk).
      void
      updated(const State<dim> &state,
              const std::size_t first,
              const std::size_t last) override;

    private:
      std::vector<std::unique_ptr<Postprocess::Postprocessor<dim>>> list;
      /// Those of list that observe updated chunks.
      std::vector<Postprocess::Postprocessor<dim> *> observers;
      const Postprocess::Reference<dim>             *reference = nullptr;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
