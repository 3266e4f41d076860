// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/base/fnv1a.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

namespace psmpm
{
  using namespace dealii;

  namespace
  {
    const char *type_names[] = {"doubles", "integers", "bytes", "text"};

    const char *checksum_attribute = "psmpm_checksum";

    /// Closes an HDF5 identifier with @p close when it goes out of scope.
    struct Handle
    {
      hid_t id;
      herr_t (*close)(hid_t);
      Handle(const hid_t id, herr_t (*close)(hid_t))
        : id(id)
        , close(close)
      {
      }
      Handle(const Handle &) = delete;
      Handle &
      operator=(const Handle &) = delete;
      ~Handle()
      {
        if (id >= 0)
          close(id);
      }
      /// Close now; false if closing failed (the data may not be written).
      bool
      release()
      {
        const herr_t r = id >= 0 ? close(id) : 0;
        id             = -1;
        return r >= 0;
      }
      operator hid_t() const
      {
        return id;
      }
    };

    /// HDF5 prints its error stack to stderr by default; psmpm reports
    /// failures itself, naming the file.
    void
    silence_hdf5()
    {
      H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }

    std::vector<hsize_t>
    dimensions(const Archive::Entry &e, const std::size_t n)
    {
      if (e.shape.empty())
        return {static_cast<hsize_t>(n)};
      return std::vector<hsize_t>(e.shape.begin(), e.shape.end());
    }



    /// Write the entry @p e as the dataset @p name of the open HDF5 file
    /// @p f (groups along the name created through @p links); false if
    /// HDF5 fails.
    bool
    write_dataset(const hid_t           f,
                  const hid_t           links,
                  const std::string    &name,
                  const Archive::Entry &e)
    {
      using Type                    = Archive::Type;
      const std::size_t n           = e.type == Type::real    ? e.reals.size() :
                                      e.type == Type::integer ? e.integers.size() :
                                                                e.data.size();
      const auto        dims        = dimensions(e, n);
      hid_t             memory_type = H5T_NATIVE_DOUBLE;
      hid_t             file_type   = H5T_IEEE_F64LE;
      const void       *data        = e.reals.data();
      Handle            text_type(-1, H5Tclose);
      Handle            space(-1, H5Sclose);
      const char       *text = e.data.c_str();
      if (e.type == Type::integer)
        {
          memory_type = H5T_NATIVE_UINT64;
          file_type   = H5T_STD_U64LE;
          data        = e.integers.data();
        }
      else if (e.type == Type::bytes)
        {
          memory_type = H5T_NATIVE_UINT8;
          file_type   = H5T_STD_U8LE;
          data        = e.data.data();
        }
      if (e.type == Type::text)
        {
          // A scalar variable-length string: h5dump shows it as text.
          text_type.id = H5Tcopy(H5T_C_S1);
          H5Tset_size(text_type, H5T_VARIABLE);
          H5Tset_cset(text_type, H5T_CSET_UTF8);
          memory_type = file_type = text_type;
          data                    = &text;
          space.id                = H5Screate(H5S_SCALAR);
        }
      else
        space.id = H5Screate_simple(dims.size(), dims.data(), nullptr);
      Handle set(H5Dcreate2(f,
                            name.c_str(),
                            file_type,
                            space,
                            links,
                            H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose);
      if (set < 0 ||
          (n > 0 || e.type == Type::text ?
             H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) <
               0 :
             false))
        return false;
      return set.release();
    }



    /// Attach the checksum @p sum to the open HDF5 file @p f; false if
    /// HDF5 fails.
    bool
    write_checksum(const hid_t f, const std::uint64_t sum)
    {
      Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
      Handle attribute(H5Acreate2(f,
                                  checksum_attribute,
                                  H5T_STD_U64LE,
                                  scalar,
                                  H5P_DEFAULT,
                                  H5P_DEFAULT),
                       H5Aclose);
      return !(attribute < 0 ||
               H5Awrite(attribute, H5T_NATIVE_UINT64, &sum) < 0 ||
               !attribute.release());
    }
  } // namespace



  void
  Archive::put(const std::string         &name,
               const std::vector<double> &values,
               const unsigned int         columns)
  {
    Entry e;
    e.type  = Type::real;
    e.reals = values;
    if (columns > 0)
      {
        AssertThrow(values.size() % columns == 0, ExcInternalError());
        e.shape = {values.size() / columns, columns};
      }
    entries[name] = std::move(e);
  }



  void
  Archive::put(const std::string &name, const double value)
  {
    put(name, std::vector<double>{value});
  }



  void
  Archive::put_integers(const std::string                &name,
                        const std::vector<std::uint64_t> &values)
  {
    Entry e;
    e.type        = Type::integer;
    e.integers    = values;
    entries[name] = std::move(e);
  }



  void
  Archive::put_integer(const std::string &name, const std::uint64_t value)
  {
    put_integers(name, {value});
  }



  void
  Archive::put_bytes(const std::string &name, const std::string &bytes)
  {
    Entry e;
    e.type        = Type::bytes;
    e.data        = bytes;
    entries[name] = std::move(e);
  }



  void
  Archive::put_text(const std::string &name, const std::string &text)
  {
    Entry e;
    e.type        = Type::text;
    e.data        = text;
    entries[name] = std::move(e);
  }



  const Archive::Entry &
  Archive::entry(const std::string &name, const Type type) const
  {
    const auto it = entries.find(name);
    AssertThrow(it != entries.end(),
                ExcMessage("entry '" + name + "' is missing"));
    AssertThrow(it->second.type == type,
                ExcMessage("entry '" + name + "' holds " +
                           type_names[static_cast<int>(it->second.type)] +
                           ", expected " + type_names[static_cast<int>(type)]));
    return it->second;
  }



  const std::vector<double> &
  Archive::get(const std::string &name, const long long size) const
  {
    const auto &v = entry(name, Type::real).reals;
    AssertThrow(size < 0 || v.size() == static_cast<std::size_t>(size),
                ExcMessage("entry '" + name + "' has " +
                           std::to_string(v.size()) + " values, expected " +
                           std::to_string(size)));
    return v;
  }



  double
  Archive::get_number(const std::string &name) const
  {
    return get(name, 1)[0];
  }



  const std::vector<std::uint64_t> &
  Archive::get_integers(const std::string &name, const long long size) const
  {
    const auto &v = entry(name, Type::integer).integers;
    AssertThrow(size < 0 || v.size() == static_cast<std::size_t>(size),
                ExcMessage("entry '" + name + "' has " +
                           std::to_string(v.size()) + " values, expected " +
                           std::to_string(size)));
    return v;
  }



  std::uint64_t
  Archive::get_integer(const std::string &name) const
  {
    return get_integers(name, 1)[0];
  }



  const std::string &
  Archive::get_bytes(const std::string &name) const
  {
    return entry(name, Type::bytes).data;
  }



  const std::string &
  Archive::get_text(const std::string &name) const
  {
    return entry(name, Type::text).data;
  }



  void
  Archive::erase_prefix(const std::string &prefix)
  {
    for (auto it = entries.begin(); it != entries.end();)
      if (it->first.rfind(prefix, 0) == 0)
        it = entries.erase(it);
      else
        ++it;
  }



  std::uint64_t
  Archive::checksum() const
  {
    std::uint64_t h = fnv1a_basis;
    for (const auto &[name, e] : entries)
      {
        h              = fnv1a(h, name.data(), name.size());
        const int type = static_cast<int>(e.type);
        h              = fnv1a(h, &type, sizeof(type));
        std::size_t n  = e.type == Type::real    ? e.reals.size() :
                         e.type == Type::integer ? e.integers.size() :
                                                   e.data.size();
        for (const hsize_t d : dimensions(e, n))
          {
            const std::uint64_t d64 = d;
            h                       = fnv1a(h, &d64, sizeof(d64));
          }
        h = fnv1a(h, e.reals.data(), e.reals.size() * sizeof(double));
        h = fnv1a(h,
                  e.integers.data(),
                  e.integers.size() * sizeof(std::uint64_t));
        h = fnv1a(h, e.data.data(), e.data.size());
      }
    return h;
  }



  void
  Archive::write_hdf5(const std::string &file, const std::string &target) const
  {
    silence_hdf5();
    const std::string name =
      target.empty() ? file : target + " (written as " + file + ")";
    const auto fail = [&name](const std::string &what) {
      throw ExcWriteFailed("cannot write " + name + ": " + what);
    };
    inject_write_failure(target.empty() ? file : target);
    {
      Handle f(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
               H5Fclose);
      if (f < 0)
        fail(std::string("cannot create the HDF5 file (") +
             (errno != 0 ? std::strerror(errno) : "HDF5 error") + ")");
      // Groups along the names are created as needed.
      Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
      H5Pset_create_intermediate_group(links, 1);

      for (const auto &[name, e] : entries)
        if (!write_dataset(f, links, name, e))
          fail("cannot write the dataset '" + name + "' (disk full?)");
      if (!write_checksum(f, checksum()))
        fail("cannot write the checksum attribute");
      if (H5Fflush(f, H5F_SCOPE_GLOBAL) < 0 || !f.release())
        fail("cannot close the HDF5 file (disk full?)");
    }
    // Closed is not on disk: the rename that publishes the file must not
    // overtake its content after a crash.
    const int fd = ::open(file.c_str(), O_RDONLY);
    if (fd < 0 || ::fsync(fd) != 0)
      {
        const int error = errno;
        if (fd >= 0)
          ::close(fd);
        fail(std::string("fsync failed (") + std::strerror(error) + ")");
      }
    ::close(fd);
  }



  namespace
  {
    struct VisitData
    {
      Archive    *archive;
      std::string error;
    };

#if H5_VERSION_GE(1, 12, 0)
    using ObjectInfo = H5O_info2_t;
#else
    using ObjectInfo     = H5O_info_t;
#endif

    /**
     * Read the values of the dataset @p set of HDF5 type @p type, @p n
     * values in @p rank dimensions, into @p e, setting its type; returns
     * what is wrong with the dataset, empty if nothing.
     */
    std::string
    read_values(const hid_t       set,
                const hid_t       type,
                const int         rank,
                const std::size_t n,
                Archive::Entry   &e)
    {
      const H5T_class_t c = H5Tget_class(type);
      herr_t            r = 0;
      if (c == H5T_STRING)
        {
          if (!H5Tis_variable_str(type) || rank != 0)
            return "is not a variable-length string";
          Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
          H5Tset_size(memory, H5T_VARIABLE);
          H5Tset_cset(memory, H5T_CSET_UTF8);
          char *text = nullptr;
          r = H5Dread(set, memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, &text);
          if (r >= 0 && text != nullptr)
            {
              e.data = text;
              H5free_memory(text);
            }
          e.type = Archive::Type::text;
        }
      else if (c == H5T_FLOAT)
        {
          e.type = Archive::Type::real;
          e.reals.resize(n);
          if (n > 0)
            r = H5Dread(set,
                        H5T_NATIVE_DOUBLE,
                        H5S_ALL,
                        H5S_ALL,
                        H5P_DEFAULT,
                        e.reals.data());
        }
      else if (c == H5T_INTEGER && H5Tget_size(type) == 8)
        {
          e.type = Archive::Type::integer;
          e.integers.resize(n);
          if (n > 0)
            r = H5Dread(set,
                        H5T_NATIVE_UINT64,
                        H5S_ALL,
                        H5S_ALL,
                        H5P_DEFAULT,
                        e.integers.data());
        }
      else if (c == H5T_INTEGER && H5Tget_size(type) == 1)
        {
          e.type = Archive::Type::bytes;
          e.data.resize(n);
          if (n > 0)
            r = H5Dread(set,
                        H5T_NATIVE_UINT8,
                        H5S_ALL,
                        H5S_ALL,
                        H5P_DEFAULT,
                        &e.data[0]);
        }
      else
        return "has a type psmpm does not write";
      if (r < 0)
        return "cannot be read (truncated or damaged file)";
      return "";
    }



    /// Put the entry @p e read as dataset @p name of dimensions @p dims
    /// into @p a (a table of doubles keeps its columns).
    void
    put_entry(Archive                    &a,
              const char                 *name,
              const Archive::Entry       &e,
              const std::vector<hsize_t> &dims)
    {
      switch (e.type)
        {
          case Archive::Type::real:
            a.put(name, e.reals, dims.size() > 1 ? dims[1] : 0);
            break;
          case Archive::Type::integer:
            a.put_integers(name, e.integers);
            break;
          case Archive::Type::bytes:
            a.put_bytes(name, e.data);
            break;
          case Archive::Type::text:
            a.put_text(name, e.data);
            break;
        }
    }



    /// Read one dataset into the archive (H5Ovisit callback).
    herr_t
    read_object(hid_t             root,
                const char       *name,
                const ObjectInfo *info,
                void             *op_data)
    {
      auto &visit = *static_cast<VisitData *>(op_data);
      if (info->type != H5O_TYPE_DATASET)
        return 0;
      const auto fail = [&visit, name](const std::string &what) {
        visit.error = "dataset '" + std::string(name) + "': " + what;
        return -1;
      };
      Handle set(H5Dopen2(root, name, H5P_DEFAULT), H5Dclose);
      if (set < 0)
        return fail("cannot be opened");
      Handle type(H5Dget_type(set), H5Tclose);
      Handle space(H5Dget_space(set), H5Sclose);
      if (type < 0 || space < 0)
        return fail("has no type or shape");
      const int rank = H5Sget_simple_extent_ndims(space);
      if (rank < 0)
        return fail("has no shape");
      std::vector<hsize_t> dims(rank);
      H5Sget_simple_extent_dims(space, dims.data(), nullptr);
      std::size_t n = 1;
      for (const auto d : dims)
        n *= d;

      Archive::Entry    e;
      const std::string problem = read_values(set, type, rank, n, e);
      if (!problem.empty())
        return fail(problem);
      if (rank > 1)
        e.shape.assign(dims.begin(), dims.end());
      put_entry(*visit.archive, name, e, dims);
      return 0;
    }
  } // namespace



  Archive
  Archive::read_hdf5(const std::string &file)
  {
    silence_hdf5();
    const auto fail = [&file](const std::string &what) {
      AssertThrow(false, ExcMessage("checkpoint " + file + ": " + what));
    };
    Archive archive;
#if H5_VERSION_GE(1, 12, 0)
    const htri_t is_hdf5 = H5Fis_accessible(file.c_str(), H5P_DEFAULT);
#else
    const htri_t is_hdf5 = H5Fis_hdf5(file.c_str());
#endif
    if (is_hdf5 <= 0)
      fail("not an HDF5 file (truncated or damaged)");
    Handle f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (f < 0)
      fail("cannot be opened as an HDF5 file (truncated or damaged)");
    VisitData visit{&archive, ""};
#if H5_VERSION_GE(1, 12, 0)
    const herr_t visited = H5Ovisit3(f,
                                     H5_INDEX_NAME,
                                     H5_ITER_INC,
                                     read_object,
                                     &visit,
                                     H5O_INFO_BASIC);
#else
    const herr_t visited = H5Ovisit2(f,
                                     H5_INDEX_NAME,
                                     H5_ITER_INC,
                                     read_object,
                                     &visit,
                                     H5O_INFO_BASIC);
#endif
    if (visited < 0)
      fail(visit.error.empty() ? "cannot be read (truncated or damaged)" :
                                 visit.error);

    std::uint64_t stored = 0;
    Handle attribute(H5Aopen(f, checksum_attribute, H5P_DEFAULT), H5Aclose);
    if (attribute < 0 || H5Aread(attribute, H5T_NATIVE_UINT64, &stored) < 0)
      fail("has no checksum (not a psmpm checkpoint, or incomplete)");
    if (stored != archive.checksum())
      fail("checksum mismatch: the file is damaged");
    return archive;
  }
} // namespace psmpm
