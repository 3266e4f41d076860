// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/fnv1a.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace psmpm
{
  std::optional<std::uint64_t>
  fnv1a_of_file(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in.is_open() || std::filesystem::is_directory(file))
      return std::nullopt;
    std::uint64_t     hash = fnv1a_basis;
    std::vector<char> block(1 << 16);
    while (in)
      {
        in.read(block.data(), block.size());
        hash = fnv1a(hash, block.data(), in.gcount());
      }
    if (in.bad())
      return std::nullopt;
    return hash;
  }
} // namespace psmpm
