// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_prefetch_h
#define psmpm_base_prefetch_h

#include <cstddef>

namespace psmpm
{
  /**
   * How many particles ahead a particle loop requests the arrays it is
   * the first of the step's update to read.
   *
   * The update of a time step runs over the particles in chunks of 512
   * (TransferScheme::move_and_update_material): each chunk is moved,
   * updated, summed into the statistics, located and added to the grid
   * while it is in the cache. Every array is therefore read in runs of
   * 512 elements, a few kB, and the loop that first reads an array in a
   * chunk (the velocity gradient reading the basis, the rotation
   * statistic reading the initial positions, ...) waited for memory at
   * the start of every run and page, which the hardware prefetcher
   * learns anew (doc/performance.md, "Prefetching the chunks' arrays").
   * 64 particles ahead is 0.6-3 us of work per loop for
   * Powell-Sabin, 0.2-0.6 us for P1, and 25 kB of a chunk's arrays:
   * against 16, 32 gave lumped P1 a 9 % shorter loop and 64 another 5 %,
   * with Powell-Sabin within the noise (paired runs on the throughput
   * bar).
   */
  constexpr std::size_t prefetch_distance = 64;

  /**
   * Request the cache lines of the @p bytes from @p begin, which the
   * caller knows to lie in an array. A hint only (no value changes, so
   * the results are the same bits with or without it). One request per
   * 64 B line: an element of at most 64 B needs one (a loop that requests
   * every element's first line in turn requests every line of the
   * array), the basis of a Powell-Sabin particle (72 B of values, 144 B
   * of gradients) two and three (the line a request leaves out is the
   * first of the next particle's).
   */
  template <std::size_t bytes = 1>
  inline void
  prefetch_lines(const void *begin)
  {
    const char *p = static_cast<const char *>(begin);
    for (std::size_t b = 0; b < bytes; b += 64)
      __builtin_prefetch(p + b);
  }
} // namespace psmpm

#endif
