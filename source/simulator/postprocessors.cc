// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/postprocessors.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    Postprocessors<dim>::declare_parameters(ParameterHandler &prm)
    {
      // A postprocessor of one dimension only is on one list.
      const auto &registry_2d =
        Postprocess::PostprocessorRegistry<2>::instance();
      const auto &registry_1d =
        Postprocess::PostprocessorRegistry<1>::instance();
      registry_2d.declare_parameters(prm);
      for (const auto &name : registry_1d.variant_names())
        if (!registry_2d.has(name))
          registry_1d.declare_parameters(name, prm);
    }

    template <int dim>
    void
    Postprocessors<dim>::parse_parameters(ParameterHandler &prm)
    {
      const auto &registry =
        Postprocess::PostprocessorRegistry<dim>::instance();
      list.clear();
      observers.clear();
      reference = nullptr;
      // variant_names() is sorted: equal orders run by name.
      for (const auto &name : registry.variant_names())
        {
          list.push_back(registry.create(name, "postprocessor"));
          list.back()->parse_parameters(prm);
        }
      std::stable_sort(list.begin(),
                       list.end(),
                       [](const auto &a, const auto &b) {
                         return a->order() < b->order();
                       });
      for (const auto &p : list)
        if (p->observes_updated_chunks())
          observers.push_back(p.get());
    }

    template <int dim>
    void
    Postprocessors<dim>::check_mesh(const Mesh::CellLocator<dim> &locator,
                                    MPI_Comm                      comm) const
    {
      for (const auto &p : list)
        p->check_mesh(locator, comm);
    }

    template <int dim>
    void
    Postprocessors<dim>::initialize(const Postprocess::StateView<dim> &view)
    {
      reference = view.reference;
      for (const auto &p : list)
        p->initialize(view);
    }

    template <int dim>
    void
    Postprocessors<dim>::start(const Postprocess::StateView<dim> &view)
    {
      for (const auto &p : list)
        p->start(view);
    }

    template <int dim>
    void
    Postprocessors<dim>::updated(const State<dim> &state,
                                 const std::size_t first,
                                 const std::size_t last)
    {
      Postprocess::StateView<dim> view = state;
      view.reference                   = reference;
      // Schemes that carry affine matrices are not observed.
      view.carries_affine = false;
      for (const auto p : observers)
        p->updated(view, first, last);
    }

    template <int dim>
    void
    Postprocessors<dim>::execute(const Postprocess::StateView<dim> &view,
                                 Postprocess::StatisticsTable      &statistics)
    {
      for (const auto &p : list)
        p->execute(view, statistics);
    }

    template <int dim>
    Postprocess::EnergyBalance
    Postprocessors<dim>::energy_balance() const
    {
      Postprocess::EnergyBalance balance;
      for (const auto &p : list)
        if (p->energy_balance(balance))
          break;
      return balance;
    }

    template <int dim>
    void
    Postprocessors<dim>::write(const Postprocess::StateView<dim> &view)
    {
      for (const auto &p : list)
        p->write(view);
    }

    template <int dim>
    void
    Postprocessors<dim>::save(Archive &archive) const
    {
      for (const auto &p : list)
        p->save(archive);
    }

    template <int dim>
    void
    Postprocessors<dim>::load(const Archive &archive)
    {
      for (const auto &p : list)
        p->load(archive);
    }

    template <int dim>
    void
    Postprocessors<dim>::fill_summary(const Postprocess::StateView<dim> &view,
                                      Summary &summary) const
    {
      for (const auto &p : list)
        p->fill_summary(view, summary);
    }

    template class Postprocessors<1>;
    template class Postprocessors<2>;
  } // namespace Simulator
} // namespace psmpm
