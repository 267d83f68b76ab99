// Small RAII and writing helpers over the HDF5 C API (private to engine/output/src).
#pragma once

#include <hdf5.h>
#include <paddy/io/h5_file.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace paddy::io::h5 {

// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5: cannot " + what + paddy::h5::systemCause());
  }
  ~Handle() { if (id_ >= 0) close_(id_); }
  // Closes now and reports a failure (closing a file writes what HDF5 still buffers).
  void close(const std::string& what) {
    if (id_ < 0) return;
    const herr_t st = close_(id_);
    id_ = -1;
    if (st < 0) throw std::runtime_error("HDF5: cannot " + what + paddy::h5::systemCause());
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  Closer close_;
};

// Writes a 1-D (cols == 0) or 2-D (rows × cols) dataset of `type` from `data`.
void writeDataset(hid_t parent, const std::string& name, hid_t type, std::size_t rows, std::size_t cols,
                  const void* data);
void writeAttribute(hid_t object, const std::string& name, double value);
void writeAttribute(hid_t object, const std::string& name, std::uint64_t value);
void writeAttribute(hid_t object, const std::string& name, const std::string& value);  // fixed-length

}  // namespace paddy::io::h5
