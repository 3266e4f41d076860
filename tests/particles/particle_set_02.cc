// ParticleSet growth: set_capacity() gives every array exactly that
// capacity (dropping add()'s doubling slack), unpack() beyond the capacity
// grows to an eighth more than needed (not std::vector's doubling), and
// resize_per_particle() sizes a work array to the particle count with the
// particle arrays' capacity. Doubling on an MPI rank that gained one particle
// copied and first-touched twice its arrays (125 ms in one step with 490,000
// particles, doc/performance.md).
#include <psmpm/particles/particle_set.h>

#include "../tests.h"

using namespace psmpm;

int
main()
{
  return run_test([]() {
    std::ofstream                  out("output");
    Particles::ParticleSet<2>      set;
    const std::vector<std::string> state{"a", "b"};
    set.set_state_names(state);
    const std::size_t n = 8000;
    for (std::size_t i = 0; i < n; ++i)
      set.add(i, 0, Point<2>(0.1, 0.2), 1e-3, 2.);
    PSMPM_CHECK(out, set.capacity() > n); // add()'s doubling
    set.set_capacity(n);
    PSMPM_CHECK(out, set.capacity() == n);
    PSMPM_CHECK(out, set.velocity.capacity() == n);
    PSMPM_CHECK(out, set.state.capacity() == n * state.size());
    PSMPM_CHECK(out, set.id[n - 1] == n - 1);

    // One particle arrives.
    std::vector<double> buffer;
    set.pack(0, buffer);
    set.unpack(buffer);
    const std::size_t grown = set.capacity();
    out << "size " << set.size() << ", capacity " << grown << std::endl;
    PSMPM_CHECK(out, grown == (n + 1) + (n + 1) / 8);
    PSMPM_CHECK(out, set.id.capacity() >= grown);
    PSMPM_CHECK(out, set.position.capacity() >= grown);
    PSMPM_CHECK(out, set.state.capacity() >= grown * state.size());

    // More arrivals within the headroom do not reallocate.
    const Point<2> *before = set.position.data();
    for (unsigned int k = 0; k < (n + 1) / 8; ++k)
      set.unpack(buffer);
    PSMPM_CHECK(out, set.size() == grown);
    PSMPM_CHECK(out, set.position.data() == before);

    // Work arrays follow the particle arrays.
    std::vector<double> work;
    Particles::resize_per_particle(work, set, 3);
    PSMPM_CHECK(out, work.size() == 3 * set.size());
    PSMPM_CHECK(out, work.capacity() >= 3 * set.capacity());
    set.unpack(buffer); // beyond the capacity: the set grows by an eighth
    const double *work_before = work.data();
    Particles::resize_per_particle(work, set, 3);
    PSMPM_CHECK(out, work.size() == 3 * set.size());
    PSMPM_CHECK(out, work.capacity() == 3 * set.capacity());
    PSMPM_CHECK(out, work.data() != work_before);
    out << "size " << set.size() << ", capacity " << set.capacity()
        << std::endl;
  });
}
