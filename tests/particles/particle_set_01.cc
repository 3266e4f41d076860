// ParticleSet in 1D and 2D: add() zeroes the kinematics and the material
// state, pack()/unpack() round trip with n_packed() doubles per particle in
// the documented order, compress() keeps the order of the survivors and
// sort_by_cell() is a stable sort by cell; the state block moves with its
// particle throughout.
#include <psmpm/particles/particle_set.h>

#include "../tests.h"

#include <algorithm>
#include <numeric>

using namespace psmpm;

/// Give particle @p i values that tell it apart from all others.
template <int dim>
void
mark(Particles::ParticleSet<dim> &set, const std::size_t i)
{
  const double s = 1 + i;
  for (unsigned int d = 0; d < dim; ++d)
    {
      set.displacement[i][d] = 10 * s + d;
      set.velocity[i][d]     = 20 * s + d;
      set.position[i][d] += 0.5;
    }
  for (unsigned int k = 0; k < set.stress[i].n_independent_components; ++k)
    set.stress[i].access_raw_entry(k) = 30 * s + k;
  for (unsigned int k = 0; k < set.n_state(); ++k)
    set.state_of(i)[k] = 40 * s + k;
  for (unsigned int d = 0; d < dim; ++d)
    for (unsigned int e = 0; e < dim; ++e)
      set.affine[i][d][e] = 50 * s + dim * d + e;
}

/// Whether particle @p i of @p a equals particle @p j of @p b (all but
/// the cell).
template <int dim>
bool
same(const Particles::ParticleSet<dim> &a,
     const std::size_t                  i,
     const Particles::ParticleSet<dim> &b,
     const std::size_t                  j)
{
  return a.id[i] == b.id[j] && a.mass[i] == b.mass[j] &&
         a.volume[i] == b.volume[j] && a.density[i] == b.density[j] &&
         a.position[i] == b.position[j] &&
         a.initial_position[i] == b.initial_position[j] &&
         a.displacement[i] == b.displacement[j] &&
         a.velocity[i] == b.velocity[j] && a.stress[i] == b.stress[j] &&
         a.affine[i] == b.affine[j] &&
         std::equal(a.state_of(i),
                    a.state_of(i) + a.n_state(),
                    b.state_of(j),
                    b.state_of(j) + b.n_state());
}

template <int dim>
void
check(std::ofstream &out)
{
  out << "dim = " << dim << std::endl;
  Particles::ParticleSet<dim> set;
  set.set_state_names({"strain_xx", "plastic"});
  const std::vector<unsigned int> cells = {2, 0, 1, 0, 2, 1, 0};
  for (std::size_t i = 0; i < cells.size(); ++i)
    {
      Point<dim> x;
      x[0] = i;
      set.add(100 + i, cells[i], x, 0.5 + i, 2.0);
    }
  bool zero = set.state.size() == cells.size() * set.n_state();
  for (std::size_t i = 0; i < set.size(); ++i)
    zero = zero && set.velocity[i].norm() == 0 &&
           set.displacement[i].norm() == 0 && set.stress[i].norm() == 0 &&
           set.affine[i].norm() == 0 && set.state_of(i)[0] == 0 &&
           set.state_of(i)[1] == 0 &&
           set.mass[i] == set.volume[i] * set.density[i];
  PSMPM_CHECK(out, zero);
  for (std::size_t i = 0; i < set.size(); ++i)
    mark(set, i);
  const Particles::ParticleSet<dim> original = set;

  // pack/unpack round trip; the layout: id, mass, ..., stress, state.
  out << "n_packed " << set.n_packed() << std::endl;
  std::vector<double> buffer;
  set.pack(3, buffer);
  set.pack(5, buffer);
  PSMPM_CHECK(out, buffer.size() == 2 * set.n_packed());
  const unsigned int n_stress =
    SymmetricTensor<2, dim>::n_independent_components;
  PSMPM_CHECK(out,
              buffer[0] == set.id[3] && buffer[1] == set.mass[3] &&
                buffer[4] == set.position[3][0] &&
                buffer[4 + 3 * dim] == set.velocity[3][0] &&
                buffer[4 + 4 * dim] == set.stress[3].access_raw_entry(0) &&
                buffer[4 + 4 * dim + n_stress] == set.state_of(3)[0] &&
                buffer[set.n_packed()] == set.id[5]);
  Particles::ParticleSet<dim> received;
  received.set_state_names(set.get_state_names());
  received.unpack(buffer);
  PSMPM_CHECK(out,
              received.size() == 2 && same(received, 0, set, 3) &&
                same(received, 1, set, 5));

  // compress keeps the survivors in order.
  const std::vector<bool> keep = {true, false, true, true, false, true, true};
  set.compress(keep);
  std::vector<std::size_t> survivors;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i])
      survivors.push_back(i);
  bool kept = set.size() == survivors.size() &&
              set.state.size() == survivors.size() * set.n_state();
  for (std::size_t j = 0; kept && j < survivors.size(); ++j)
    kept = same(set, j, original, survivors[j]) &&
           set.cell[j] == original.cell[survivors[j]];
  PSMPM_CHECK(out, kept);

  // sort_by_cell: a stable sort of the survivors by cell.
  std::vector<std::size_t> order = survivors;
  std::stable_sort(order.begin(),
                   order.end(),
                   [&original](const std::size_t a, const std::size_t b) {
                     return original.cell[a] < original.cell[b];
                   });
  set.sort_by_cell(3);
  bool sorted = set.size() == order.size();
  for (std::size_t j = 0; sorted && j < order.size(); ++j)
    sorted = same(set, j, original, order[j]) &&
             set.cell[j] == original.cell[order[j]];
  PSMPM_CHECK(out, sorted);
  out << "ids after compress and sort:";
  for (const auto id : set.id)
    out << ' ' << id;
  out << std::endl;

  // The state layout cannot change under existing particles.
  bool threw = false;
  try
    {
      set.set_state_names({"one"});
    }
  catch (const std::exception &)
    {
      threw = true;
    }
  PSMPM_CHECK(out, threw);
}

int
main()
{
  std::ofstream out("output");
  check<1>(out);
  check<2>(out);
}
