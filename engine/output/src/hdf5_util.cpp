// HDF5 writing helpers, see hdf5_util.hpp.
#include "hdf5_util.hpp"

namespace paddy::io::h5 {

void writeDataset(hid_t parent, const std::string& name, hid_t type, std::size_t rows, std::size_t cols,
                  const void* data) {
  hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)};
  Handle space(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose, "create dataspace for " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  if (rows > 0 && H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw std::runtime_error("HDF5: cannot write dataset " + name + paddy::h5::systemCause());
}

namespace {
void writeScalarAttribute(hid_t object, const std::string& name, hid_t type, const void* value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create dataspace for attribute " + name);
  Handle attr(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              "create attribute " + name);
  if (H5Awrite(attr, type, value) < 0)
    throw std::runtime_error("HDF5: cannot write attribute " + name + paddy::h5::systemCause());
}
}  // namespace

void writeAttribute(hid_t object, const std::string& name, double value) {
  writeScalarAttribute(object, name, H5T_NATIVE_DOUBLE, &value);
}

void writeAttribute(hid_t object, const std::string& name, std::uint64_t value) {
  writeScalarAttribute(object, name, H5T_NATIVE_UINT64, &value);
}

void writeAttribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "create string type for attribute " + name);
  // Null-terminated: the size counts the terminating '\0' that c_str() provides.
  if (H5Tset_size(type, value.size() + 1) < 0) throw std::runtime_error("HDF5: cannot size string attribute " + name);
  writeScalarAttribute(object, name, type, value.c_str());
}

}  // namespace paddy::io::h5
