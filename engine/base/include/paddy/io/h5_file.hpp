// Minimal RAII wrapper over the HDF5 C API for the engine's own files (checkpoints, wall load
// histories): 1-D or N×k datasets of doubles and integers addressed by "group/name" (groups are
// created on the way), and scalar attributes (numbers, variable-length UTF-8 strings) on the
// root or on any group or dataset.
#pragma once

#include <hdf5.h>

#include <paddy/errors.hpp>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace paddy::h5 {

// The operating system's reason for the HDF5 call that just failed, read from the error stack
// (the file driver records "errno = 27, error message = 'File too large'"): ": File too large",
// or "" when the failure was not a system call's. Call it right after the failing call: the next
// HDF5 call clears the stack.
inline std::string systemCause() {
  std::string found;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
        if (!e->desc) return 0;
        const std::string d = e->desc;
        const std::string key = "error message = '";
        const auto k = d.find(key);
        if (k == std::string::npos) return 0;
        const auto end = d.find('\'', k + key.size());
        *static_cast<std::string*>(data) = d.substr(k + key.size(), end == std::string::npos ? std::string::npos : end - k - key.size());
        return 1;
      },
      &found);
  return found.empty() ? std::string() : ": " + found;
}

template <class T>
hid_t nativeType() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  else if constexpr (std::is_same_v<T, std::uint64_t>) return H5T_NATIVE_UINT64;
  else if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  else static_assert(sizeof(T) == 0, "unsupported HDF5 element type");
}

class File {
 public:
  static File create(const std::string& path) {
    hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (id < 0) throw InputError("cannot create HDF5 file '" + path + "'" + systemCause());
    return File(id, path);
  }
  static File open(const std::string& path) {
    hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw InputError("cannot open HDF5 file '" + path + "' (missing or not HDF5)");
    return File(id, path);
  }
  File(File&& o) noexcept : id_(o.id_), path_(std::move(o.path_)) { o.id_ = -1; }
  File(const File&) = delete;
  ~File() {
    if (id_ >= 0) H5Fclose(id_);
  }
  // Closes the file, writing what HDF5 still buffers: a full disk or `ulimit -f` may show only
  // here. Call it before using a written file (the destructor cannot report a failure).
  void close() {
    if (id_ < 0) return;
    const herr_t st = H5Fclose(id_);
    id_ = -1;
    if (st < 0) throw InputError("cannot write HDF5 file '" + path_ + "'" + systemCause());
  }

  template <class T>
  void write(const std::string& name, const std::vector<T>& data, hsize_t columns = 1) {
    hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lcpl, 1);
    const hsize_t dims[2] = {static_cast<hsize_t>(data.size() / columns), columns};
    hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
    hid_t set = H5Dcreate2(id_, name.c_str(), nativeType<T>(), space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = set < 0 ? -1
                : data.empty() ? 0
                               : H5Dwrite(set, nativeType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    if (st < 0) {
      const std::string cause = systemCause();
      if (set >= 0) H5Dclose(set);
      H5Sclose(space);
      H5Pclose(lcpl);
      throw InputError("cannot write dataset '" + name + "' to '" + path_ + "'" + cause);
    }
    H5Dclose(set);
    H5Sclose(space);
    H5Pclose(lcpl);
  }

  // Reads a dataset as write() wrote it: rank 1 when `columns` is 1, else rank 2 with that many
  // columns, elements of T's kind (floating point or integer of T's sign) and size. Another
  // shape or kind, or storage smaller than the data (a dataset declared large but never written,
  // or compressed: write() does neither) is refused with an InputError naming the file and the
  // dataset, before anything is allocated: a hostile file cannot make it allocate more than the
  // file holds.
  template <class T>
  std::vector<T> read(const std::string& name, hsize_t columns = 1) const {
    const std::string where = "HDF5 file '" + path_ + "': dataset '" + name + "'";
    hid_t set = H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0 ? H5Dopen2(id_, name.c_str(), H5P_DEFAULT) : -1;
    if (set < 0) throw InputError("HDF5 file '" + path_ + "' has no dataset '" + name + "'");
    const hid_t space = H5Dget_space(set), type = H5Dget_type(set);
    std::string why;
    hsize_t dims[2] = {0, 0};
    const int rank = space < 0 ? -1 : H5Sget_simple_extent_ndims(space);
    const H5T_class_t cls = type < 0 ? H5T_NO_CLASS : H5Tget_class(type);
    const bool floating = std::is_floating_point_v<T>;
    if (cls != (floating ? H5T_FLOAT : H5T_INTEGER) || H5Tget_size(type) != sizeof(T) ||
        (!floating && H5Tget_sign(type) != (std::is_signed_v<T> ? H5T_SGN_2 : H5T_SGN_NONE)))
      why = std::string(" does not hold ") + (floating ? "64-bit floating-point numbers"
                                              : std::is_signed_v<T> ? "64-bit signed integers"
                                                                    : "64-bit unsigned integers");
    else if (H5Sget_simple_extent_type(space) != H5S_SIMPLE || rank != (columns == 1 ? 1 : 2))
      why = " has " + std::to_string(rank < 0 ? 0 : rank) + " dimensions, expected " + (columns == 1 ? "1" : "2");
    else if (H5Sget_simple_extent_dims(space, dims, nullptr) < 0 || (columns != 1 && dims[1] != columns))
      why = " has " + std::to_string(dims[1]) + " columns, expected " + std::to_string(columns);
    else if (dims[0] > (hsize_t{1} << 40) / columns)
      why = " has " + std::to_string(dims[0]) + " rows, more than any file holds";
    const hsize_t n = why.empty() ? dims[0] * columns : 0;
    if (why.empty() && n > 0 && H5Dget_storage_size(set) < n * sizeof(T))
      why = " declares " + std::to_string(n) + " values but stores " + std::to_string(H5Dget_storage_size(set)) +
            " bytes (never written, truncated or compressed)";
    std::vector<T> out;
    herr_t st = 0;
    if (why.empty()) {
      out.resize(static_cast<std::size_t>(n));
      st = n > 0 ? H5Dread(set, nativeType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) : 0;
      if (st < 0) why = " cannot be read" + systemCause();
    }
    if (type >= 0) H5Tclose(type);
    if (space >= 0) H5Sclose(space);
    H5Dclose(set);
    if (!why.empty()) throw InputError(where + why);
    return out;
  }

  void writeAttr(const std::string& name, double value) {
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t attr = H5Acreate2(id_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
    const herr_t st = attr >= 0 ? H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) : -1;
    const std::string cause = st < 0 ? systemCause() : std::string();
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(space);
    if (st < 0) throw InputError("cannot write attribute '" + name + "' to '" + path_ + "'" + cause);
  }
  // Scalar attribute `name` on the group or dataset at `object` ("/" = the root).
  void writeAttr(const std::string& object, const std::string& name, double value) {
    writeObjectAttr(object, name, H5T_NATIVE_DOUBLE, &value);
  }
  void writeAttr(const std::string& object, const std::string& name, std::uint64_t value) {
    writeObjectAttr(object, name, H5T_NATIVE_UINT64, &value);
  }
  void writeAttr(const std::string& object, const std::string& name, const std::string& value) {
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const char* text = value.c_str();
    try {
      writeObjectAttr(object, name, type, &text);
    } catch (...) {
      H5Tclose(type);
      throw;
    }
    H5Tclose(type);
  }
  // A number stored as a scalar attribute of the root (integer or floating point); anything else
  // (missing, text, an array, unreadable) is refused naming the file and the attribute.
  double readAttr(const std::string& name) const {
    hid_t attr = H5Aexists(id_, name.c_str()) > 0 ? H5Aopen(id_, name.c_str(), H5P_DEFAULT) : -1;
    if (attr < 0) throw InputError("HDF5 file '" + path_ + "' has no attribute '" + name + "'");
    const hid_t space = H5Aget_space(attr), type = H5Aget_type(attr);
    const H5T_class_t cls = type < 0 ? H5T_NO_CLASS : H5Tget_class(type);
    double v = 0.0;
    const bool number = (cls == H5T_INTEGER || cls == H5T_FLOAT) && space >= 0 &&
                        H5Sget_simple_extent_npoints(space) == 1 && H5Aread(attr, H5T_NATIVE_DOUBLE, &v) >= 0;
    if (type >= 0) H5Tclose(type);
    if (space >= 0) H5Sclose(space);
    H5Aclose(attr);
    if (!number) throw InputError("HDF5 file '" + path_ + "': attribute '" + name + "' is not a single number");
    return v;
  }

 private:
  File(hid_t id, std::string path) : id_(id), path_(std::move(path)) {}
  void writeObjectAttr(const std::string& object, const std::string& name, hid_t type, const void* value) {
    hid_t obj = H5Oopen(id_, object.c_str(), H5P_DEFAULT);
    if (obj < 0) throw InputError("HDF5 file '" + path_ + "' has no object '" + object + "'");
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t attr = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    const herr_t st = attr >= 0 ? H5Awrite(attr, type, value) : -1;
    const std::string cause = st < 0 ? systemCause() : std::string();
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(space);
    H5Oclose(obj);
    if (st < 0) throw InputError("cannot write attribute '" + name + "' of '" + object + "' to '" + path_ + "'" + cause);
  }
  hid_t id_ = -1;
  std::string path_;
};

}  // namespace paddy::h5
