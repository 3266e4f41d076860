// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_fnv1a_h
#define psmpm_base_fnv1a_h

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace psmpm
{
  /// The offset basis of the 64-bit FNV-1a hash: the hash of no bytes.
  constexpr std::uint64_t fnv1a_basis = 14695981039346656037ULL;

  /// The 64-bit FNV-1a hash @p h continued over @p n bytes at @p data
  /// (start with fnv1a_basis). A checksum that recognises damaged or
  /// changed content, not a cryptographic one.
  inline std::uint64_t
  fnv1a(std::uint64_t h, const void *data, const std::size_t n)
  {
    const auto *bytes = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < n; ++i)
      {
        h ^= bytes[i];
        h *= 1099511628211ULL;
      }
    return h;
  }

  /// The 64-bit FNV-1a hash of the bytes of @p file; none if it cannot
  /// be opened or read, or is a directory.
  std::optional<std::uint64_t>
  fnv1a_of_file(const std::string &file);
} // namespace psmpm

#endif
