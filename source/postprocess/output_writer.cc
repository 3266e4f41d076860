// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/postprocess/output_writer.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <tuple>
#include <zlib.h>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      using Ranges = DataRanges;

      const char component_suffix[] = {'x', 'y', 'z'};

      std::string
      piece_name(const std::string &base,
                 const unsigned int step,
                 const unsigned int rank)
      {
        return base + "-" + Utilities::int_to_string(step, 5) + "." +
               Utilities::int_to_string(rank, 3) + ".vtu";
      }

      /// Append the dim components of vector @p name ("name_x", ...).
      template <int dim>
      void
      add_vector(const std::string        &name,
                 std::vector<std::string> &names,
                 Ranges                   &ranges)
      {
        ranges.emplace_back(
          names.size(),
          names.size() + dim - 1,
          name,
          DataComponentInterpretation::component_is_part_of_vector);
        for (unsigned int d = 0; d < dim; ++d)
          names.push_back(name + "_" + component_suffix[d]);
      }

      /// The VTU flags of every piece and record: zlib-compressed binary,
      /// compressed for speed (the output is written during the run).
      DataOutBase::VtkFlags
      vtk_flags()
      {
        DataOutBase::VtkFlags flags;
        flags.compression_level = DataOutBase::VtkFlags::best_speed;
        return flags;
      }

      /// Write this rank's piece with @p write_piece and, on rank 0, the
      /// .pvtu record; return the name of the record for the .pvd series.
      std::string
      write_pieces(const std::string                         &directory,
                   const std::string                         &base,
                   const unsigned int                         step,
                   const std::vector<std::string>            &names,
                   const Ranges                              &ranges,
                   const std::function<void(std::ostream &)> &write_piece,
                   MPI_Comm                                   comm)
      {
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
        const unsigned int size = Utilities::MPI::n_mpi_processes(comm);
        {
          const std::string file =
            directory + "/" + piece_name(base, step, rank);
          // A piece that cannot be written whole is removed, whatever
          // stopped it (a full disk, or an error inside the writer).
          std::ofstream out(file, std::ios::binary);
          try
            {
              check_written(out, file);
              try
                {
                  write_piece(out);
                }
              catch (const ExcWriteFailed &)
                {
                  throw;
                }
              catch (...)
                {
                  check_written(out, file); // deal.II's ExcIO: say why
                  throw;
                }
              check_written(out, file);
            }
          catch (...)
            {
              out.close();
              std::remove(file.c_str());
              throw;
            }
        }
        const std::string record =
          base + "-" + Utilities::int_to_string(step, 5) + ".pvtu";
        if (rank == 0)
          {
            std::vector<std::string> pieces;
            for (unsigned int r = 0; r < size; ++r)
              pieces.push_back(piece_name(base, step, r));
            write_atomically(directory + "/" + record, [&](std::ostream &out) {
              DataOutBase::write_pvtu_record(out,
                                             pieces,
                                             names,
                                             ranges,
                                             vtk_flags());
            });
          }
        return record;
      }



      /**
       * One inline binary DataArray of a VTU file, zlib-compressed, in the
       * layout of VTK's vtkZLibDataCompressor that DataOutBase::write_vtu()
       * writes: a header of UInt32 words (number of blocks, bytes per
       * block, bytes of the last block, compressed bytes of each block)
       * base64-encoded on its own, then the compressed blocks as one
       * base64 stream.
       *
       * Why not deal.II: write_vtu() takes one Patch per point, which for
       * the particles cost about 336 B per particle and set the peak
       * memory of a run (doc/performance.md). Here the values are pushed
       * one by one and go through zlib and base64 in chunks of
       * chunk_bytes, so memory stays at a few chunks (and zlib's state)
       * whatever the number of values. The compressed sizes are only known
       * at the end, so the header (whose length the number of values
       * fixes) is written as a placeholder and overwritten then, as VTK's
       * own writer does: the stream must be seekable (a file).
       *
       * An array is one block, as deal.II writes it (and as the tests' and
       * contrib/ readers expect), unless it is larger than max_block_bytes
       * (the UInt32 header's limit, where deal.II stops): then blocks of
       * max_block_bytes, which VTK reads just as well.
       */
      class CompressedArrayWriter
      {
      public:
        static constexpr std::size_t chunk_bytes     = 1 << 16;
        static constexpr std::size_t max_block_bytes = std::size_t(1) << 31;
        static_assert(max_block_bytes % chunk_bytes == 0,
                      "block boundaries must fall on chunk boundaries");

        explicit CompressedArrayWriter(const int level)
          : chunk(chunk_bytes)
          , compressed(chunk_bytes)
          , text(4 * (chunk_bytes / 3 + 2))
        {
          stream.zalloc = Z_NULL;
          stream.zfree  = Z_NULL;
          stream.opaque = Z_NULL;
          AssertThrow(deflateInit(&stream, level) == Z_OK,
                      ExcMessage("psmpm: zlib could not be initialised."));
        }

        ~CompressedArrayWriter()
        {
          deflateEnd(&stream);
        }

        CompressedArrayWriter(const CompressedArrayWriter &) = delete;
        CompressedArrayWriter &
        operator=(const CompressedArrayWriter &) = delete;

        /// Start an array of @p n_bytes bytes on @p out.
        void
        begin(std::ostream &out, const std::size_t n_bytes)
        {
          this->out   = &out;
          total_bytes = n_bytes;
          block_bytes = std::min(n_bytes, max_block_bytes);
          n_blocks    = n_bytes == 0 ?
                          0 :
                          (n_bytes + max_block_bytes - 1) / max_block_bytes;
          compressed_sizes.clear();
          AssertThrow(deflateReset(&stream) == Z_OK, ExcInternalError());
          n_chunk = n_block = n_pushed = block_compressed = 0;
          n_carry                                         = 0;
          if (n_blocks == 0)
            {
              // A rank without particles: a header of zero blocks, which
              // VTK reads without complaint (an empty element it does not).
              out << "AAAAAAAAAAAAAAAA";
              return;
            }
          header_position = out.tellp();
          AssertThrow(header_position != std::streampos(-1),
                      ExcMessage("psmpm: VTU output needs a seekable file."));
          const std::string placeholder(base64_length(header_bytes()), 'A');
          out << placeholder;
        }

        template <typename T>
        void
        push(const T value)
        {
          static_assert(chunk_bytes % sizeof(T) == 0,
                        "values must not straddle chunks");
          std::memcpy(chunk.data() + n_chunk, &value, sizeof(T));
          n_chunk += sizeof(T);
          if (n_chunk == chunk_bytes)
            flush_chunk();
        }

        /// Compress what is left, then write the header in its place.
        void
        end()
        {
          AssertThrow(n_pushed + n_chunk == total_bytes, ExcInternalError());
          if (n_blocks == 0)
            return;
          if (n_chunk > 0 || compressed_sizes.size() < n_blocks)
            {
              n_block += n_chunk;
              deflate_chunk(Z_FINISH);
              compressed_sizes.push_back(block_compressed);
            }
          AssertThrow(compressed_sizes.size() == n_blocks, ExcInternalError());
          if (n_carry > 0)
            {
              write_base64(carry, n_carry, true);
              n_carry = 0;
            }

          std::vector<std::uint32_t> header = {
            static_cast<std::uint32_t>(n_blocks),
            static_cast<std::uint32_t>(block_bytes),
            static_cast<std::uint32_t>(
              n_blocks == 1 ? total_bytes : total_bytes % max_block_bytes)};
          for (const std::size_t s : compressed_sizes)
            {
              AssertThrow(s <= std::numeric_limits<std::uint32_t>::max(),
                          ExcInternalError());
              header.push_back(static_cast<std::uint32_t>(s));
            }
          const std::streampos end_position = out->tellp();
          out->seekp(header_position);
          write_base64(reinterpret_cast<const unsigned char *>(header.data()),
                       header_bytes(),
                       true);
          out->seekp(end_position);
        }

      private:
        std::size_t
        header_bytes() const
        {
          return (3 + n_blocks) * sizeof(std::uint32_t);
        }

        static std::size_t
        base64_length(const std::size_t n)
        {
          return 4 * ((n + 2) / 3);
        }

        void
        flush_chunk()
        {
          n_block += n_chunk;
          n_pushed += n_chunk;
          const bool block_full = (n_block == max_block_bytes);
          deflate_chunk(block_full ? Z_FINISH : Z_NO_FLUSH);
          n_chunk = 0;
          if (block_full)
            {
              compressed_sizes.push_back(block_compressed);
              block_compressed = 0;
              n_block          = 0;
              AssertThrow(deflateReset(&stream) == Z_OK, ExcInternalError());
            }
        }

        /// Feed the chunk to zlib and its output to base64.
        void
        deflate_chunk(const int flush)
        {
          stream.next_in  = chunk.data();
          stream.avail_in = static_cast<uInt>(n_chunk);
          for (;;)
            {
              stream.next_out  = compressed.data();
              stream.avail_out = static_cast<uInt>(compressed.size());
              const int result = deflate(&stream, flush);
              // Z_BUF_ERROR: no progress possible, which with output space
              // left is only harmless without Z_FINISH.
              AssertThrow(result == Z_OK || result == Z_STREAM_END ||
                            (result == Z_BUF_ERROR && flush != Z_FINISH),
                          ExcMessage("psmpm: zlib compression failed."));
              const std::size_t produced = compressed.size() - stream.avail_out;
              block_compressed += produced;
              encode(compressed.data(), produced);
              if (flush == Z_FINISH ? result == Z_STREAM_END :
                                      stream.avail_out != 0)
                break;
            }
        }

        /// Append @p n bytes to the base64 stream; up to two bytes wait in
        /// carry for the next call (or end()).
        void
        encode(const unsigned char *data, std::size_t n)
        {
          while (n_carry > 0 && n_carry < 3 && n > 0)
            {
              carry[n_carry++] = *data++;
              --n;
            }
          if (n_carry == 3)
            {
              write_base64(carry, 3, false);
              n_carry = 0;
            }
          const std::size_t whole = n - n % 3;
          write_base64(data, whole, false);
          for (std::size_t k = whole; k < n; ++k)
            carry[n_carry++] = data[k];
        }

        /// Base64 of @p n bytes (a multiple of 3 unless @p last) to out.
        void
        write_base64(const unsigned char *data,
                     const std::size_t    n,
                     const bool           last)
        {
          static const char table[] =
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
          std::size_t done = 0;
          while (done < n)
            {
              // At most text.size() characters per write.
              const std::size_t n_bytes =
                std::min(n - done, (text.size() / 4) * 3);
              std::size_t          length = 0;
              const unsigned char *d      = data + done;
              std::size_t          k      = 0;
              for (; k + 3 <= n_bytes; k += 3)
                {
                  const std::uint32_t v = (std::uint32_t(d[k]) << 16) |
                                          (std::uint32_t(d[k + 1]) << 8) |
                                          d[k + 2];
                  text[length++] = table[(v >> 18) & 63];
                  text[length++] = table[(v >> 12) & 63];
                  text[length++] = table[(v >> 6) & 63];
                  text[length++] = table[v & 63];
                }
              if (k < n_bytes)
                {
                  // Padding ends a base64 stream.
                  AssertThrow(last, ExcInternalError());
                  const std::uint32_t v =
                    (std::uint32_t(d[k]) << 16) |
                    (k + 1 < n_bytes ? std::uint32_t(d[k + 1]) << 8 : 0);
                  text[length++] = table[(v >> 18) & 63];
                  text[length++] = table[(v >> 12) & 63];
                  text[length++] = k + 1 < n_bytes ? table[(v >> 6) & 63] : '=';
                  text[length++] = '=';
                }
              out->write(text.data(), length);
              done += n_bytes;
            }
        }

        z_stream                   stream;
        std::vector<unsigned char> chunk;
        std::vector<unsigned char> compressed;
        std::vector<char>          text;
        std::ostream              *out = nullptr;
        std::streampos             header_position;
        std::size_t                total_bytes = 0;
        std::size_t                block_bytes = 0;
        std::size_t                n_blocks    = 0;
        std::vector<std::size_t>   compressed_sizes;
        std::size_t                n_chunk          = 0;
        std::size_t                n_block          = 0;
        std::size_t                n_pushed         = 0;
        std::size_t                block_compressed = 0;
        unsigned char              carry[3];
        std::size_t                n_carry = 0;
      };



      /// One VTU data array: the opening tag with @p attributes, then the
      /// @p n_entries x @p n_components values of component(i, c) as T
      /// (points: n entries, cells: n_cells), compressed by @p writer.
      template <typename T, typename Component>
      void
      write_data_array(std::ostream          &out,
                       CompressedArrayWriter &writer,
                       const std::string     &attributes,
                       const std::size_t      n_entries,
                       const unsigned int     n_components,
                       const Component       &component)
      {
        out << "    <DataArray " << attributes << " format=\"binary\">\n";
        writer.begin(out, n_entries * n_components * sizeof(T));
        for (std::size_t i = 0; i < n_entries; ++i)
          for (unsigned int c = 0; c < n_components; ++c)
            writer.push(static_cast<T>(component(i, c)));
        writer.end();
        out << "\n    </DataArray>\n";
      }

      /// The output components of one vector or tensor @p range at the
      /// VTK positions (3 for a vector, 3 x 3 row by row for a tensor):
      /// source[c] is the component at position c, or invalid (written
      /// as 0); marks them in @p written.
      std::array<unsigned int, 9>
      vtk_sources(const Ranges::value_type &range,
                  const bool                is_tensor,
                  std::vector<bool>        &written)
      {
        const unsigned int          first = std::get<0>(range);
        const unsigned int          last  = std::get<1>(range);
        std::array<unsigned int, 9> source;
        source.fill(numbers::invalid_unsigned_int);
        const unsigned int size = last - first + 1;
        AssertThrow(is_tensor ? (size == 1 || size == 4) : size <= 3,
                    ExcInternalError());
        for (unsigned int c = 0; c < size; ++c)
          {
            written[first + c] = true;
            if (!is_tensor)
              source[c] = first + c;
            else if (size == 1)
              source[0] = first;
            else
              {
                const auto ind = Tensor<2, 2>::unrolled_to_component_indices(c);
                source[3 * ind[0] + ind[1]] = first + c;
              }
          }
        return source;
      }

      /// The point data of write_cells_vtu(): as deal.II, the vectors and
      /// tensors of @p ranges, then the other scalars of @p names.
      template <typename Value>
      void
      write_point_data(std::ostream                   &out,
                       CompressedArrayWriter          &writer,
                       const std::size_t               n,
                       const std::vector<std::string> &names,
                       const Ranges                   &ranges,
                       const Value                    &value)
      {
        out << "  <PointData Scalars=\"scalars\">\n";
        std::vector<bool> written(names.size(), false);
        for (const auto &range : ranges)
          {
            const bool is_tensor =
              std::get<3>(range) ==
              DataComponentInterpretation::component_is_part_of_tensor;
            const std::array<unsigned int, 9> source =
              vtk_sources(range, is_tensor, written);
            const std::string &name = std::get<2>(range);
            AssertThrow(!name.empty(), ExcInternalError());
            write_data_array<float>(
              out,
              writer,
              "type=\"Float32\" Name=\"" + name + "\" NumberOfComponents=\"" +
                std::to_string(is_tensor ? 9 : 3) + "\"",
              n,
              is_tensor ? 9 : 3,
              [&](const std::size_t i, const unsigned int c) {
                return source[c] == numbers::invalid_unsigned_int ?
                         0. :
                         value(i, source[c]);
              });
          }
        for (unsigned int k = 0; k < names.size(); ++k)
          if (!written[k])
            write_data_array<float>(out,
                                    writer,
                                    "type=\"Float32\" Name=\"" + names[k] +
                                      "\"",
                                    n,
                                    1,
                                    [&](const std::size_t i, unsigned int) {
                                      return value(i, k);
                                    });
        out << "  </PointData>\n";
      }

      /**
       * The VTU piece of @p n_cells cells of @p vertices_per_cell points
       * each (VTK cell type @p vtk_type; points not shared, cell i is the
       * points i * vertices_per_cell, ...), point j at @p position(j) (a
       * Point<dim>), with the point data @p names / @p ranges, component k
       * of point j being @p value(j, k): the file DataOutBase::write_vtu()
       * writes for one Patch<0, dim> per point (VTK_VERTEX, one vertex) or
       * one simplex Patch<2, 2> with n_subdivisions = 1 per triangle
       * (VTK_TRIANGLE, three) -- its header and footer, the same arrays in
       * the same order, Float32 values, vectors padded to 3 and tensors to
       * 3 x 3 components, row by row -- written array by array straight
       * from the values, without the patches (for particles about 336 B
       * each, for a triangle more than 1 kB; a Powell-Sabin grid of
       * 1.28M cells drawn as 16 sub-triangles each ran out of 24 GB).
       */
      template <int dim, typename Position, typename Value>
      void
      write_cells_vtu(std::ostream                   &out,
                      const std::size_t               n_cells,
                      const unsigned int              vertices_per_cell,
                      const std::uint8_t              vtk_type,
                      const std::vector<std::string> &names,
                      const Ranges                   &ranges,
                      const Position                 &position,
                      const Value                    &value)
      {
        const std::size_t n = n_cells * vertices_per_cell;
        AssertThrow(n < std::size_t(std::numeric_limits<std::int32_t>::max()),
                    ExcMessage("psmpm: too many points for one VTU piece "
                               "(Int32 connectivity)."));
        const DataOutBase::VtkFlags flags = vtk_flags();
        CompressedArrayWriter       writer(Z_BEST_SPEED); // as best_speed

        DataOutBase::write_vtu_header(out, flags);
        out << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\""
            << n_cells << "\" >\n";
        out << "  <Points>\n";
        write_data_array<float>(out,
                                writer,
                                "type=\"Float32\" NumberOfComponents=\"3\"",
                                n,
                                3,
                                [&](const std::size_t i, const unsigned int c) {
                                  return c < dim ? position(i)[c] : 0.;
                                });
        out << "  </Points>\n\n";
        out << "  <Cells>\n";
        write_data_array<std::int32_t>(out,
                                       writer,
                                       "type=\"Int32\" Name=\"connectivity\"",
                                       n,
                                       1,
                                       [](const std::size_t i, unsigned int) {
                                         return i;
                                       });
        write_data_array<std::int32_t>(out,
                                       writer,
                                       "type=\"Int32\" Name=\"offsets\"",
                                       n_cells,
                                       1,
                                       [vertices_per_cell](const std::size_t i,
                                                           unsigned int) {
                                         return (i + 1) * vertices_per_cell;
                                       });
        write_data_array<std::uint8_t>(out,
                                       writer,
                                       "type=\"UInt8\" Name=\"types\"",
                                       n_cells,
                                       1,
                                       [vtk_type](std::size_t, unsigned int) {
                                         return vtk_type;
                                       });
        out << "  </Cells>\n";
        write_point_data(out, writer, n, names, ranges, value);
        out << " </Piece>\n";
        DataOutBase::write_vtu_footer(out);
        out << std::flush;
      }



      /**
       * The sampling points of one cell in real coordinates: in 1D the
       * s + 1 equispaced points from vertex 0 to vertex 1 (the order in
       * which deal.II reads a line patch with n_subdivisions = s); in 2D
       * the (s + 1)(s + 2) / 2 points v0 + i/s (v1 - v0) + j/s (v2 - v0),
       * i + j <= s, row by row in j (see lattice_index()).
       */
      template <int dim>
      std::vector<Point<dim>>
      lattice_points(const std::array<Point<dim>, dim + 1> &v,
                     const unsigned int                     s)
      {
        std::vector<Point<dim>> points;
        if constexpr (dim == 1)
          for (unsigned int i = 0; i <= s; ++i)
            points.push_back(v[0] + (double(i) / s) * (v[1] - v[0]));
        else
          for (unsigned int j = 0; j <= s; ++j)
            for (unsigned int i = 0; i + j <= s; ++i)
              {
                Point<dim> p = v[0];
                p += (double(i) / s) * (v[1] - v[0]);
                p += (double(j) / s) * (v[dim] - v[0]);
                points.push_back(p);
              }
        return points;
      }

      /// The (s + 1)^2 points v0 + i/s (v1 - v0) + j/s (v2 - v0),
      /// 0 <= i, j <= s, i fastest: the order in which deal.II reads a
      /// quadrilateral patch with n_subdivisions = s (2D, rectangles).
      std::vector<Point<2>>
      box_lattice_points(const std::array<Point<2>, 3> &v, const unsigned int s)
      {
        std::vector<Point<2>> points;
        for (unsigned int j = 0; j <= s; ++j)
          for (unsigned int i = 0; i <= s; ++i)
            points.push_back(v[0] + (double(i) / s) * (v[1] - v[0]) +
                             (double(j) / s) * (v[2] - v[0]));
        return points;
      }

      /// Position of lattice point (i, j) in lattice_points() (2D).
      unsigned int
      lattice_index(const unsigned int i,
                    const unsigned int j,
                    const unsigned int s)
      {
        return j * (s + 1) - j * (j - 1) / 2 + i;
      }

      /**
       * The s^2 sub-triangles of the lattice as point triples, oriented as
       * the cell: the "upward" ones (i, j), (i+1, j), (i, j+1) and the
       * "downward" ones (i+1, j), (i+1, j+1), (i, j+1).
       */
      std::vector<std::array<unsigned int, 3>>
      sub_triangles(const unsigned int s)
      {
        std::vector<std::array<unsigned int, 3>> triangles;
        for (unsigned int j = 0; j < s; ++j)
          for (unsigned int i = 0; i + j < s; ++i)
            {
              triangles.push_back({{lattice_index(i, j, s),
                                    lattice_index(i + 1, j, s),
                                    lattice_index(i, j + 1, s)}});
              if (i + j + 1 < s)
                triangles.push_back({{lattice_index(i + 1, j, s),
                                      lattice_index(i + 1, j + 1, s),
                                      lattice_index(i, j + 1, s)}});
            }
        return triangles;
      }

      /// Append the material state to the output components: groups of
      /// scalars <p>_xx, <p>_xy (, <p>_yx), <p>_yy become one dim x dim
      /// tensor, the others stay scalars; @p source receives the state
      /// index of each appended component.
      template <int dim>
      void
      state_layout(const std::vector<std::string> &state_names,
                   std::vector<std::string>       &names,
                   Ranges                         &ranges,
                   std::vector<unsigned int>      &source)
      {
        const auto index = [&state_names](const std::string &n) {
          const auto it = std::find(state_names.begin(), state_names.end(), n);
          return it == state_names.end() ?
                   numbers::invalid_unsigned_int :
                   static_cast<unsigned int>(it - state_names.begin());
        };
        std::vector<bool> used(state_names.size(), false);
        for (unsigned int k = 0; k < state_names.size(); ++k)
          {
            const std::string &n = state_names[k];
            if (used[k] || n.size() < 4 || n.substr(n.size() - 3) != "_xx")
              continue;
            const std::string         prefix = n.substr(0, n.size() - 3);
            std::vector<unsigned int> components;
            for (unsigned int c = 0; c < dim * dim; ++c)
              {
                const auto ind =
                  Tensor<2, dim>::unrolled_to_component_indices(c);
                const std::string suffix = std::string("_") +
                                           component_suffix[ind[0]] +
                                           component_suffix[ind[1]];
                unsigned int j = index(prefix + suffix);
                if (j == numbers::invalid_unsigned_int && ind[0] > ind[1])
                  j = index(prefix + "_" + component_suffix[ind[1]] +
                            component_suffix[ind[0]]); // symmetric
                components.push_back(j);
              }
            if (std::find(components.begin(),
                          components.end(),
                          numbers::invalid_unsigned_int) != components.end())
              continue; // not a complete tensor: scalars
            ranges.emplace_back(
              names.size(),
              names.size() + dim * dim - 1,
              prefix,
              DataComponentInterpretation::component_is_part_of_tensor);
            for (unsigned int c = 0; c < dim * dim; ++c)
              {
                const auto ind =
                  Tensor<2, dim>::unrolled_to_component_indices(c);
                names.push_back(prefix + "_" + component_suffix[ind[0]] +
                                component_suffix[ind[1]]);
                source.push_back(components[c]);
                used[components[c]] = true;
              }
          }
        for (unsigned int k = 0; k < state_names.size(); ++k)
          if (!used[k])
            {
              names.push_back(state_names[k]);
              source.push_back(k);
            }
      }

      /**
       * The particle output's components and their values: id, cell,
       * rank, mass, volume, density (body_id and material_id with
       * Bodies), displacement, velocity, the stress and the material
       * state. The constructor fills the names and ranges of the
       * components; operator()(i, k) is component k of particle i, in the
       * order of names. VTU stores Float32: ids above 2^24 lose their
       * last digits, which is acceptable for picking particles in
       * ParaView.
       */
      template <int dim>
      class ParticleValues
      {
      public:
        ParticleValues(const Particles::ParticleSet<dim> &particles,
                       const double                       rank,
                       std::vector<std::string>          &names,
                       Ranges                            &ranges)
          : particles(particles)
          , rank(rank)
        {
          names = {"id", "cell", "rank", "mass", "volume", "density"};
          // Scenes without Bodies keep their fields (every particle is in
          // body 0).
          if (particles.n_bodies > 0)
            {
              names.push_back("body_id");
              names.push_back("material_id");
            }
          first_displacement = names.size();
          add_vector<dim>("displacement", names, ranges);
          first_velocity = names.size();
          add_vector<dim>("velocity", names, ranges);

          // The full dim x dim tensor in deal.II's unrolled order, so that
          // ParaView shows the symmetric stress as a tensor (eigenvalues,
          // von Mises through the calculator) rather than loose
          // components.
          first_stress = names.size();
          for (unsigned int c = 0; c < dim * dim; ++c)
            {
              stress_index[c] =
                Tensor<2, dim>::unrolled_to_component_indices(c);
              names.push_back(std::string("stress_") +
                              component_suffix[stress_index[c][0]] +
                              component_suffix[stress_index[c][1]]);
            }
          ranges.emplace_back(
            first_stress,
            first_stress + dim * dim - 1,
            "stress",
            DataComponentInterpretation::component_is_part_of_tensor);

          // Material state: scalars named <p>_xx, <p>_xy, ... form a
          // tensor (a symmetric one if <p>_yx is missing), written as
          // such; the rest are scalars.
          first_state = names.size();
          state_layout<dim>(particles.get_state_names(), names, ranges, source);
        }

        double
        operator()(const std::size_t i, const unsigned int k) const
        {
          if (k >= first_state)
            return particles.state_of(i)[source[k - first_state]];
          if (k >= first_stress)
            {
              const TableIndices<2> &ind = stress_index[k - first_stress];
              return particles.stress[i][ind[0]][ind[1]];
            }
          if (k >= first_velocity)
            return particles.velocity[i][k - first_velocity];
          if (k >= first_displacement)
            return particles.displacement[i][k - first_displacement];
          switch (k)
            {
              case 0:
                return static_cast<double>(particles.id[i]);
              case 1:
                return particles.cell[i];
              case 2:
                return rank;
              case 3:
                return particles.mass[i];
              case 4:
                return particles.volume[i];
              case 5:
                return particles.density[i];
              case 6:
                return particles.body_id[i];
              default:
                return particles.body_material[particles.body_id[i]];
            }
        }

      private:
        const Particles::ParticleSet<dim> &particles;
        const double                       rank;
        unsigned int first_displacement, first_velocity, first_stress,
          first_state;
        /// The state index of output component first_state + k.
        std::vector<unsigned int>              source;
        std::array<TableIndices<2>, dim * dim> stress_index;
      };

      template <int dim>
      using VectorFields = std::vector<
        std::pair<std::string, const std::vector<Tensor<1, dim>> *>>;
      using ScalarFields =
        std::vector<std::pair<std::string, const std::vector<double> *>>;

      /**
       * The grid output sampled cell by cell: the field values at the
       * sampling points of each cell (lattice_points()), collected as one
       * patch per cell in 1D and on rectangles (Mesh/Type = cartesian),
       * and on triangles as the drawn lattice points and their values,
       * cell after cell, written without patches (write_cells_vtu()).
       * Components of a point: on a moved grid how far it moved (ParaView
       * can colour by it; the points are already at the moved positions),
       * the vector fields, the scalar fields and the rank (a cell field;
       * VTU patches only carry point data, so it is constant on the
       * cell's unshared points, which ParaView shows as cells).
       */
      template <int dim>
      class GridSampler
      {
      public:
        GridSampler(const Basis::Space<dim>         &space,
                    const std::vector<unsigned int> &cell_dofs,
                    const VectorFields<dim>         &vector_fields,
                    const ScalarFields              &scalar_fields,
                    const std::vector<Point<dim>>   *moved_vertices,
                    const unsigned int               subdivisions,
                    const double                     rank)
          : space(space)
          , n(space.dofs_per_cell())
          , cell_dofs(cell_dofs)
          , vector_fields(vector_fields)
          , scalar_fields(scalar_fields)
          , moved_vertices(moved_vertices)
          , s(subdivisions)
          , rank(rank)
        {
        }

        /// The component names and ranges of the output.
        void
        layout(std::vector<std::string> &names, Ranges &ranges)
        {
          if (moved_vertices)
            add_vector<dim>("grid_displacement", names, ranges);
          for (const auto &f : vector_fields)
            add_vector<dim>(f.first, names, ranges);
          for (const auto &f : scalar_fields)
            names.push_back(f.first);
          names.push_back("rank");
          n_names = names.size();
        }

        /// Sample the owned @p cell and add it to the output.
        void
        add_cell(const typename DoFHandler<dim>::active_cell_iterator &cell)
        {
          // Rectangles are drawn as one quadrilateral patch each,
          // triangles as s^2 triangles.
          const bool quad = dim == 2 && cell->reference_cell() ==
                                          ReferenceCells::get_hypercube<dim>();
          const unsigned int              c = cell->active_cell_index();
          std::array<Point<dim>, dim + 1> v;
          for (unsigned int i = 0; i <= dim; ++i)
            v[i] = cell->vertex(i);
          std::vector<Point<dim>> points;
          if constexpr (dim == 2)
            points =
              quad ? box_lattice_points(v, s) : lattice_points<dim>(v, s);
          else
            points = lattice_points<dim>(v, s);
          // On a moved grid the cell is affinely mapped: the lattice
          // point of the same barycentric coordinates carries the same
          // values, drawn at its moved position.
          std::array<Point<dim>, dim + 1> w = v;
          if (moved_vertices)
            for (unsigned int i = 0; i <= dim; ++i)
              w[i] = (*moved_vertices)[cell_dofs[c * n + i]];
          const std::vector<Point<dim>> drawn =
            moved_vertices ? lattice_points<dim>(w, s) : points;
          evaluate(c, points, drawn);

          if constexpr (dim == 1)
            // deal.II subdivides line patches itself: s + 1 points.
            add_patch(w.data(), 2, points.size());
          else if (quad)
            {
              std::array<Point<dim>, 4> corners;
              for (unsigned int i = 0; i < cell->n_vertices(); ++i)
                corners[i] = cell->vertex(i);
              add_patch(corners.data(), cell->n_vertices(), points.size());
            }
          else
            {
              // Drawn as s^2 triangles of three unshared points each, as
              // deal.II 9.4 writes one simplex patch per sub-triangle (it
              // has no simplex patches with n_subdivisions > 1).
              lattice_drawn.insert(lattice_drawn.end(),
                                   drawn.begin(),
                                   drawn.end());
              lattice_data.insert(lattice_data.end(), data.begin(), data.end());
              ++n_triangle_cells;
            }
        }

        /// The piece of the triangles (2D).
        void
        write_triangles(std::ostream                   &out,
                        const std::vector<std::string> &names,
                        const Ranges                   &ranges) const
        {
          // Point j: corner j % 3 of sub-triangle (j / 3) % T of the
          // (j / 3T)-th cell, i.e. one of the cell's L lattice points.
          const std::vector<std::array<unsigned int, 3>> triangles =
            sub_triangles(s);
          const std::size_t T     = triangles.size();
          const std::size_t L     = (s + 1) * (s + 2) / 2;
          const auto        point = [&](const std::size_t j) {
            const std::size_t cell = j / (3 * T);
            const std::size_t r    = j % (3 * T);
            return cell * L + triangles[r / 3][r % 3];
          };
          write_cells_vtu<dim>(
            out,
            n_triangle_cells * T,
            3,
            5, // VTK_TRIANGLE
            names,
            ranges,
            [&](const std::size_t j) -> const Point<dim> & {
              return lattice_drawn[point(j)];
            },
            [&](const std::size_t j, const unsigned int k) {
              return lattice_data[point(j) * n_names + k];
            });
        }

        std::vector<DataOutBase::Patch<dim, dim>> patches;
        std::size_t                               n_triangle_cells = 0;

      private:
        /// The field values at the sampling @p points of cell @p c (drawn
        /// at @p drawn) into data, point-major, with one batched
        /// (virtual) evaluation.
        void
        evaluate(const unsigned int             c,
                 const std::vector<Point<dim>> &points,
                 const std::vector<Point<dim>> &drawn)
        {
          const unsigned int n_points = points.size();
          cells.assign(n_points, c);
          values.resize(n_points * n);
          space.evaluate(n_points,
                         cells.data(),
                         points.data(),
                         values.data(),
                         nullptr);
          data.assign(n_points * n_names, 0.);
          for (unsigned int q = 0; q < n_points; ++q)
            {
              const double *phi = values.data() + q * n;
              double       *row = data.data() + q * n_names;
              if (moved_vertices)
                for (unsigned int d = 0; d < dim; ++d)
                  *row++ = drawn[q][d] - points[q][d];
              for (const auto &f : vector_fields)
                {
                  Tensor<1, dim> u;
                  for (unsigned int k = 0; k < n; ++k)
                    u += phi[k] * (*f.second)[cell_dofs[c * n + k]];
                  for (unsigned int d = 0; d < dim; ++d)
                    *row++ = u[d];
                }
              for (const auto &f : scalar_fields)
                {
                  double u = 0;
                  for (unsigned int k = 0; k < n; ++k)
                    u += phi[k] * (*f.second)[cell_dofs[c * n + k]];
                  *row++ = u;
                }
              *row = rank;
            }
        }

        /// A patch of the @p n_vertices @p vertices (a line or a
        /// rectangle) with n_subdivisions = s and the values of data.
        void
        add_patch(const Point<dim>  *vertices,
                  const unsigned int n_vertices,
                  const unsigned int n_points)
        {
          DataOutBase::Patch<dim, dim> patch;
          patch.reference_cell = ReferenceCells::get_hypercube<dim>();
          patch.n_subdivisions = s;
          patch.patch_index    = patches.size();
          for (unsigned int i = 0; i < n_vertices; ++i)
            patch.vertices[i] = vertices[i];
          patch.data.reinit(n_names, n_points);
          for (unsigned int q = 0; q < n_points; ++q)
            for (unsigned int r = 0; r < n_names; ++r)
              patch.data(r, q) = data[q * n_names + r];
          patches.push_back(std::move(patch));
        }

        const Basis::Space<dim>         &space;
        const unsigned int               n;
        const std::vector<unsigned int> &cell_dofs;
        const VectorFields<dim>         &vector_fields;
        const ScalarFields              &scalar_fields;
        const std::vector<Point<dim>>   *moved_vertices;
        const unsigned int               s;
        const double                     rank;
        unsigned int                     n_names = 0;

        std::vector<Point<dim>>   lattice_drawn;
        std::vector<double>       lattice_data;
        std::vector<double>       values;
        std::vector<unsigned int> cells;
        /// Field values at the lattice points of one cell, point-major.
        std::vector<double> data;
      };
    } // namespace



    template <int dim>
    OutputWriter<dim>::OutputWriter(const std::string   &directory,
                                    MPI_Comm             comm,
                                    const unsigned int   subdivisions,
                                    const ParticleFormat particle_format)
      : directory(directory)
      , comm(comm)
      , subdivisions(subdivisions)
    {
      AssertThrow(subdivisions >= 1,
                  ExcMessage("psmpm: Output/Subdivisions must be >= 1."));
      // HDF5 (and XDMF) store points in 2 or 3 coordinates only.
      AssertThrow(particle_format == ParticleFormat::vtu || dim >= 2,
                  ExcMessage("Output/Particle format = hdf5 needs "
                             "Geometry/Dimension = 2; use vtu in 1D."));
      if (particle_format == ParticleFormat::hdf5)
        hdf5 = std::make_unique<ParticleHdf5Writer>(directory, comm);
    }



    template <int dim>
    void
    OutputWriter<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry(
        "Subdivisions",
        "0",
        Patterns::Integer(0, 16),
        "Each cell of the grid output is split into this many sub-cells per "
        "edge so that quadratic fields (Powell-Sabin) look smooth in "
        "ParaView; 1 shows the field at the corners only; 0: automatic, 1 "
        "for linear spaces and 4 for higher degrees.");
      prm.declare_entry(
        "Particle format",
        "vtu",
        Patterns::Selection("vtu|hdf5"),
        "vtu: one VTU piece per MPI rank and output, a .pvtu record and the "
        "series particles.pvd. hdf5 (2D only): one file particles-<step>.h5 "
        "per output for all ranks and the series particles.xdmf (ParaView: "
        "XDMF reader): one file per output whatever the number of ranks, "
        "but uncompressed, about 6 times larger and 4 times slower to write "
        "on one node (doc/getting_started.md); tensors (stress) are written "
        "as their components. The grid output is VTU either way.");
      prm.leave_subsection();
    }



    template <int dim>
    ParticleFormat
    OutputWriter<dim>::parse_particle_format(const std::string &name)
    {
      AssertThrow(name == "vtu" || name == "hdf5",
                  ExcMessage("Output/Particle format must be vtu or hdf5, "
                             "not '" +
                             name + "'."));
      return name == "vtu" ? ParticleFormat::vtu : ParticleFormat::hdf5;
    }



    template <int dim>
    void
    OutputWriter<dim>::write_pvd(
      const std::string                                 &name,
      const std::vector<std::pair<double, std::string>> &records) const
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_atomically(directory + "/" + name + ".pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records);
      });
    }



    template <int dim>
    void
    OutputWriter<dim>::write_particles(
      const unsigned int                 step,
      const double                       time,
      const Particles::ParticleSet<dim> &particles)
    {
      std::vector<std::string>  names;
      Ranges                    ranges;
      const ParticleValues<dim> value(particles,
                                      Utilities::MPI::this_mpi_process(comm),
                                      names,
                                      ranges);
      if constexpr (dim >= 2)
        if (hdf5)
          {
            std::vector<DataOutBase::Patch<0, dim>> patches(particles.size());
            for (std::size_t i = 0; i < particles.size(); ++i)
              {
                auto &patch       = patches[i];
                patch.vertices[0] = particles.position[i];
                patch.patch_index = i;
                patch.data.reinit(names.size(), 1);
                for (unsigned int k = 0; k < names.size(); ++k)
                  patch.data(k, 0) = value(i, k);
              }
            hdf5->write(step, time, names, ranges, patches);
            return;
          }
      // Straight from the particle arrays, not through one deal.II Patch
      // per particle (see write_cells_vtu()).
      particle_records.emplace_back(
        time,
        write_pieces(
          directory,
          "particles",
          step,
          names,
          ranges,
          [&](std::ostream &out) {
            write_cells_vtu<dim>(
              out,
              particles.size(),
              1,
              1, // VTK_VERTEX
              names,
              ranges,
              [&](const std::size_t i) -> const Point<dim> & {
                return particles.position[i];
              },
              value);
          },
          comm));
      write_pvd("particles", particle_records);
    }



    template <int dim>
    void
    OutputWriter<dim>::write_grid(
      const unsigned int               step,
      const double                     time,
      const DoFHandler<dim>           &dof_handler,
      const Basis::Space<dim>         &space,
      const std::vector<unsigned int> &cell_dofs,
      const std::vector<
        std::pair<std::string, const std::vector<Tensor<1, dim>> *>>
        &vector_fields,
      const std::vector<std::pair<std::string, const std::vector<double> *>>
                                    &scalar_fields,
      const std::vector<Point<dim>> *moved_vertices)
    {
      AssertThrow(moved_vertices == nullptr || space.dofs_per_cell() == dim + 1,
                  ExcMessage("psmpm: a moved grid is drawn for P1 (one "
                             "function per vertex) only."));
      std::vector<std::string> names;
      Ranges                   ranges;
      GridSampler<dim>         sampler(space,
                               cell_dofs,
                               vector_fields,
                               scalar_fields,
                               moved_vertices,
                               subdivisions,
                               Utilities::MPI::this_mpi_process(comm));
      sampler.layout(names, ranges);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          sampler.add_cell(cell);
      AssertThrow(sampler.patches.empty() || sampler.n_triangle_cells == 0,
                  ExcMessage("psmpm: grid output of a mesh with both "
                             "triangles and rectangles is not supported."));

      grid_records.emplace_back(time,
                                write_pieces(
                                  directory,
                                  "grid",
                                  step,
                                  names,
                                  ranges,
                                  [&](std::ostream &out) {
                                    if (dim != 2 || !sampler.patches.empty())
                                      DataOutBase::write_vtu(sampler.patches,
                                                             names,
                                                             ranges,
                                                             vtk_flags(),
                                                             out);
                                    else
                                      sampler.write_triangles(out,
                                                              names,
                                                              ranges);
                                  },
                                  comm));
      write_pvd("grid", grid_records);
    }



    namespace
    {
      void
      save_records(const std::vector<std::pair<double, std::string>> &records,
                   const std::string                                 &name,
                   Archive                                           &archive)
      {
        std::vector<double> times;
        std::string         files;
        for (const auto &r : records)
          {
            times.push_back(r.first);
            files += r.second + "\n";
          }
        archive.put("output/" + name + "_times", times);
        archive.put_text("output/" + name + "_files", files);
      }

      std::vector<std::pair<double, std::string>>
      load_records(const std::string &name, const Archive &archive)
      {
        const auto &times = archive.get("output/" + name + "_times");
        const auto  files =
          Utilities::split_string_list(archive.get_text("output/" + name +
                                                        "_files"),
                                       '\n');
        AssertThrow(files.size() >= times.size(),
                    ExcMessage("entry 'output/" + name +
                               "_files' does not match 'output/" + name +
                               "_times'"));
        std::vector<std::pair<double, std::string>> records;
        for (std::size_t i = 0; i < times.size(); ++i)
          records.emplace_back(times[i], files[i]);
        return records;
      }
    } // namespace



    template <int dim>
    void
    OutputWriter<dim>::save(Archive &archive) const
    {
      save_records(particle_records, "particles", archive);
      save_records(grid_records, "grid", archive);
      if (hdf5)
        hdf5->save(archive);
    }



    template <int dim>
    void
    OutputWriter<dim>::load(const Archive &archive)
    {
      particle_records = load_records("particles", archive);
      grid_records     = load_records("grid", archive);
      if (hdf5)
        hdf5->load(archive);
    }



    template <int dim>
    void
    OutputWriter<dim>::restore_files(const unsigned int step) const
    {
      if (hdf5)
        hdf5->write_index();
      else
        write_pvd("particles", particle_records);
      write_pvd("grid", grid_records);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      static const std::regex series(
        "(particles|grid)-([0-9]+)(\\.[0-9]+)?\\.(vtu|pvtu|h5)");
      std::error_code ec;
      for (const auto &entry :
           std::filesystem::directory_iterator(directory, ec))
        {
          std::smatch       m;
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && std::regex_match(name, m, series) &&
              std::stoull(m[2].str()) > step)
            std::filesystem::remove(entry.path(), ec);
        }
    }



    template class OutputWriter<1>;
    template class OutputWriter<2>;
  } // namespace Postprocess
} // namespace psmpm
