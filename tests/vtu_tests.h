// ---------------------------------------------------------------------
// psmpm: reading back the VTU pieces psmpm writes (tests).
// ---------------------------------------------------------------------
#ifndef psmpm_tests_vtu_tests_h
#define psmpm_tests_vtu_tests_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>
#include <zlib.h>

using namespace dealii;

/// The unsigned attribute @p key of the first <Piece> of a .vtu.
inline unsigned int
piece_attribute(const std::string &vtu, const std::string &key)
{
  const auto piece = vtu.find("<Piece ");
  const auto at    = vtu.find(key + "=\"", piece);
  AssertThrow(piece != std::string::npos && at != std::string::npos,
              ExcMessage("no " + key));
  return std::stoul(vtu.substr(at + key.size() + 2));
}

/// Decode a compressed Float32 DataArray: deal.II writes base64(header of
/// four uint32: blocks, block size, last block size, compressed size)
/// followed by base64(zlib data). @p marker locates the array
/// ("<Points>" or "Name=\"u\"").
inline std::vector<float>
read_floats(const std::string &vtu, const std::string &marker)
{
  auto at = vtu.find(marker);
  AssertThrow(at != std::string::npos, ExcMessage("no array " + marker));
  at              = vtu.find("format=\"binary\">", at);
  const auto  end = vtu.find("</DataArray>", at);
  std::string text;
  for (auto i = vtu.find('>', at) + 1; i < end; ++i)
    if (!std::isspace(static_cast<unsigned char>(vtu[i])))
      text += vtu[i];

  // 16 header bytes are 24 base64 characters.
  const std::vector<unsigned char> header =
    Utilities::decode_base64(text.substr(0, 24));
  std::uint32_t h[4];
  std::memcpy(h, header.data(), sizeof(h));
  AssertThrow(h[0] == 1, ExcMessage("expected one compressed block"));
  const std::vector<unsigned char> compressed =
    Utilities::decode_base64(text.substr(24));
  std::vector<float> data(h[1] / sizeof(float));
  uLongf             size = h[1];
  AssertThrow(uncompress(reinterpret_cast<Bytef *>(data.data()),
                         &size,
                         compressed.data(),
                         h[3]) == Z_OK,
              ExcMessage("zlib"));
  return data;
}

#endif
