// Used by fuzz_checkpoint.cpp: a checkpoint file held as data (every dataset and attribute the
// writer, engine/core/src/checkpoint.cpp, produces), changed by a list of operations decoded from
// the fuzz input, and written back as a valid HDF5 file. Byte mutation of an HDF5 file only
// breaks its checksums and B-trees (docs/reliability.md); building the file from changed
// structure reaches the checks of Paddy's reader instead: missing or extra datasets, other
// element types, shapes and row counts, NaN and infinities, huge declared sizes with no data,
// compressed storage, wrong counts, versions, steps and times.
#pragma once

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace paddy::fuzz {

enum class Kind { F64, I64, U64 };
// How a dataset or attribute is stored: as written by paddy, or in another element type.
enum class Stored { Native, F32, I32, U8, Text, SignFlipped, F64 };

struct Dataset {
  std::string name;
  Kind kind = Kind::F64;
  std::vector<double> f;         // values when kind == F64
  std::vector<std::uint64_t> u;  // values (bit patterns of int64 for I64) otherwise
  hsize_t columns = 1;
  int rank = 1;                  // 0: scalar, 1, 2 (columns > 1 needs rank 2)
  Stored stored = Stored::Native;
  hsize_t huge_rows = 0;         // > 0: declared with this many rows and never written
  bool compressed = false;       // chunked + deflate
  std::size_t size() const { return kind == Kind::F64 ? f.size() : u.size(); }
  bool operator==(const Dataset& o) const {
    return name == o.name && kind == o.kind && f.size() == o.f.size() &&
           (f.empty() || std::memcmp(f.data(), o.f.data(), f.size() * sizeof(double)) == 0) && u == o.u &&
           columns == o.columns && rank == o.rank && stored == o.stored && huge_rows == o.huge_rows &&
           compressed == o.compressed;
  }
};

struct Attribute {
  std::string name;
  double value = 0.0;
  Stored stored = Stored::F64;  // F64, I32 (as int64), F32, Text, or U8 (an array of two numbers)
  bool operator==(const Attribute& o) const {
    return name == o.name && std::memcmp(&value, &o.value, sizeof value) == 0 && stored == o.stored;
  }
};

struct Model {
  std::vector<Dataset> sets;
  std::vector<Attribute> attrs;
  bool operator==(const Model& o) const { return sets == o.sets && attrs == o.attrs; }
  Dataset* set(const std::string& name) {
    for (auto& d : sets)
      if (d.name == name) return &d;
    return nullptr;
  }
  const Attribute* attr(const std::string& name) const {
    for (const auto& a : attrs)
      if (a.name == name) return &a;
    return nullptr;
  }
};

// The datasets and attributes of a checkpoint (checkpoint.cpp), with their kinds and columns.
struct Layout {
  const char* name;
  Kind kind;
  hsize_t columns;
};
inline const std::vector<Layout>& checkpointDatasets() {
  static const std::vector<Layout> l = {
      {"particles/id", Kind::U64, 1},       {"particles/material", Kind::I64, 1}, {"particles/radius", Kind::F64, 1},
      {"particles/mass", Kind::F64, 1},     {"particles/inertia", Kind::F64, 1},  {"particles/position", Kind::F64, 3},
      {"particles/velocity", Kind::F64, 3}, {"particles/omega", Kind::F64, 3},    {"particles/force", Kind::F64, 3},
      {"particles/torque", Kind::F64, 3},   {"particles/resisting_torque", Kind::F64, 1},
      {"particles/prev_index", Kind::U64, 1}, {"list/start", Kind::U64, 1},       {"list/partner", Kind::U64, 1},
      {"list/partner_id", Kind::U64, 1},    {"list/range2", Kind::F64, 1},        {"list/law", Kind::I64, 1},
      {"list/history", Kind::F64, 1},       {"list/live", Kind::U64, 1},          {"list/x_at_build", Kind::F64, 3},
      {"walls/x_at_refresh", Kind::F64, 3}, {"walls/particle_id", Kind::U64, 1},  {"walls/wall", Kind::U64, 1},
      {"walls/key", Kind::U64, 1},          {"walls/history", Kind::F64, 1},      {"list/owner_bounds", Kind::U64, 1}};
  return l;
}
inline const std::vector<std::string>& checkpointAttributes() {
  static const std::vector<std::string> a = {"version", "time", "dt", "steps", "next_id", "list_builds", "threads",
                                             "materials", "history_stride", "list_valid", "forces_valid", "skin",
                                             "list_build_time", "walls_refreshed", "wall_refresh_time", "cell_size"};
  return a;
}

inline hid_t memType(Kind k) {
  return k == Kind::F64 ? H5T_NATIVE_DOUBLE : k == Kind::I64 ? H5T_NATIVE_INT64 : H5T_NATIVE_UINT64;
}

// Reads a checkpoint written by paddy (every dataset and attribute above must be there).
inline Model readModel(const std::string& path) {
  Model m;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) std::abort();
  for (const auto& l : checkpointDatasets()) {
    Dataset d;
    d.name = l.name;
    d.kind = l.kind;
    d.columns = l.columns;
    d.rank = l.columns == 1 ? 1 : 2;
    const hid_t set = H5Dopen2(file, l.name, H5P_DEFAULT);
    if (set < 0) std::abort();
    const hid_t space = H5Dget_space(set);
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    void* buf = nullptr;
    if (l.kind == Kind::F64) d.f.resize(n), buf = d.f.data();
    else d.u.resize(n), buf = d.u.data();
    if (n > 0 && H5Dread(set, memType(l.kind), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0) std::abort();
    H5Sclose(space);
    H5Dclose(set);
    m.sets.push_back(std::move(d));
  }
  for (const auto& name : checkpointAttributes()) {
    Attribute a;
    a.name = name;
    const hid_t at = H5Aopen(file, name.c_str(), H5P_DEFAULT);
    if (at < 0 || H5Aread(at, H5T_NATIVE_DOUBLE, &a.value) < 0) std::abort();
    H5Aclose(at);
    m.attrs.push_back(a);
  }
  H5Fclose(file);
  return m;
}

// A double as the stored type would hold it (the conversions done here, not by HDF5: NaN and
// out-of-range values of a float-to-integer conversion would be undefined behaviour).
inline std::int64_t toInt(double v, double lo, double hi) {
  if (!(v == v)) return 0;
  return static_cast<std::int64_t>(std::clamp(v, lo, hi));
}
inline double storedValue(double v, Stored s) {
  if (s == Stored::I32) return static_cast<double>(toInt(v, -9.2e18, 9.2e18));  // attributes: int64
  if (s == Stored::F32) return std::isfinite(v) ? static_cast<double>(static_cast<float>(std::clamp(v, -3e38, 3e38))) : v;
  return v;
}

// Writes a dataset; returns false when HDF5 refused to create it (then it is not in the file).
inline bool writeDataset(hid_t file, const Dataset& d) {
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const std::size_t n = d.size();
  const hsize_t cols = d.rank == 2 ? d.columns : 1;
  hsize_t dims[2] = {d.huge_rows > 0 ? d.huge_rows : (d.rank == 0 ? 1 : n / cols), cols};
  const std::size_t count = d.huge_rows > 0 ? 0 : static_cast<std::size_t>(d.rank == 0 ? std::min<std::size_t>(n, 1) : dims[0] * cols);
  const hid_t space = d.rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(d.rank, dims, nullptr);
  // Element type and a buffer converted here.
  hid_t ftype = -1, mtype = -1;
  std::vector<double> fb;
  std::vector<std::uint64_t> ub;
  std::vector<float> f32;
  std::vector<std::int32_t> i32;
  std::vector<std::uint8_t> u8;
  std::vector<char> text;
  auto asDouble = [&](std::size_t k) {
    return d.kind == Kind::F64 ? d.f[k] : d.kind == Kind::I64 ? static_cast<double>(static_cast<std::int64_t>(d.u[k]))
                                                              : static_cast<double>(d.u[k]);
  };
  const void* buf = nullptr;
  switch (d.stored) {
    case Stored::Native:
    case Stored::F64:
      ftype = d.stored == Stored::F64 ? H5T_IEEE_F64LE : d.kind == Kind::F64 ? H5T_IEEE_F64LE : d.kind == Kind::I64 ? H5T_STD_I64LE : H5T_STD_U64LE;
      if (d.stored == Stored::F64 && d.kind != Kind::F64) {
        for (std::size_t k = 0; k < count; ++k) fb.push_back(asDouble(k));
        mtype = H5T_NATIVE_DOUBLE, buf = fb.data();
      } else {
        mtype = memType(d.kind), buf = d.kind == Kind::F64 ? static_cast<const void*>(d.f.data()) : d.u.data();
      }
      break;
    case Stored::SignFlipped:
      ftype = d.kind == Kind::U64 ? H5T_STD_I64LE : H5T_STD_U64LE;
      if (d.kind == Kind::F64) ftype = H5T_STD_I64LE;
      for (std::size_t k = 0; k < count; ++k) ub.push_back(d.kind == Kind::F64 ? static_cast<std::uint64_t>(toInt(d.f[k], -9.2e18, 9.2e18)) : d.u[k]);
      mtype = ftype == H5T_STD_I64LE ? H5T_NATIVE_INT64 : H5T_NATIVE_UINT64, buf = ub.data();
      break;
    case Stored::F32:
      for (std::size_t k = 0; k < count; ++k) f32.push_back(static_cast<float>(storedValue(asDouble(k), Stored::F32)));
      ftype = H5T_IEEE_F32LE, mtype = H5T_NATIVE_FLOAT, buf = f32.data();
      break;
    case Stored::I32:
      for (std::size_t k = 0; k < count; ++k) i32.push_back(static_cast<std::int32_t>(toInt(asDouble(k), -2e9, 2e9)));
      ftype = H5T_STD_I32LE, mtype = H5T_NATIVE_INT32, buf = i32.data();
      break;
    case Stored::U8:
      for (std::size_t k = 0; k < count; ++k) u8.push_back(static_cast<std::uint8_t>(toInt(asDouble(k), 0, 255)));
      ftype = H5T_STD_U8LE, mtype = H5T_NATIVE_UINT8, buf = u8.data();
      break;
    case Stored::Text: {
      ftype = H5Tcopy(H5T_C_S1);
      H5Tset_size(ftype, 8);
      mtype = ftype;
      for (std::size_t k = 0; k < count; ++k) {
        char cell[9] = {};
        std::snprintf(cell, sizeof cell, "%g", asDouble(k));
        text.insert(text.end(), cell, cell + 8);
      }
      buf = text.data();
      break;
    }
  }
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (d.compressed && d.rank > 0 && dims[0] > 0) {
    hsize_t chunk[2] = {std::min<hsize_t>(dims[0], 64), cols};
    H5Pset_chunk(dcpl, d.rank, chunk);
    H5Pset_deflate(dcpl, 6);
  }
  const hid_t set = space < 0 ? -1 : H5Dcreate2(file, d.name.c_str(), ftype, space, lcpl, dcpl, H5P_DEFAULT);
  if (set >= 0 && count > 0) H5Dwrite(set, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  if (set >= 0) H5Dclose(set);
  if (d.stored == Stored::Text) H5Tclose(ftype);
  H5Pclose(dcpl);
  if (space >= 0) H5Sclose(space);
  H5Pclose(lcpl);
  return set >= 0;
}

inline void writeAttribute(hid_t file, const Attribute& a) {
  hid_t space = -1, type = -1;
  const double v = a.value;
  double two[2] = {v, v};
  std::int64_t i = toInt(v, -9.2e18, 9.2e18);
  float f = static_cast<float>(storedValue(v, Stored::F32));
  const char* text = "2";
  const void* buf = &v;
  hid_t mtype = H5T_NATIVE_DOUBLE;
  switch (a.stored) {
    case Stored::I32: type = H5T_STD_I64LE, mtype = H5T_NATIVE_INT64, buf = &i; break;
    case Stored::F32: type = H5T_IEEE_F32LE, mtype = H5T_NATIVE_FLOAT, buf = &f; break;
    case Stored::Text:
      type = H5Tcopy(H5T_C_S1);
      H5Tset_size(type, H5T_VARIABLE);
      mtype = type, buf = &text;
      break;
    case Stored::U8: {
      const hsize_t dims[1] = {2};
      space = H5Screate_simple(1, dims, nullptr);
      type = H5T_IEEE_F64LE, buf = two;
      break;
    }
    default: type = H5T_IEEE_F64LE; break;
  }
  if (space < 0) space = H5Screate(H5S_SCALAR);
  const hid_t at = H5Acreate2(file, a.name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (at >= 0) {
    H5Awrite(at, mtype, buf);
    H5Aclose(at);
  }
  if (a.stored == Stored::Text) H5Tclose(type);
  H5Sclose(space);
}

// Writes the model as an HDF5 file; the datasets HDF5 refused to create are dropped from it.
inline void writeModel(const std::string& path, Model& m) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) std::abort();
  for (const auto& a : m.attrs) writeAttribute(file, a);
  std::vector<Dataset> written;
  for (auto& d : m.sets)
    if (writeDataset(file, d)) written.push_back(std::move(d));
  m.sets = std::move(written);
  if (H5Fclose(file) < 0) std::abort();
}

}  // namespace paddy::fuzz
