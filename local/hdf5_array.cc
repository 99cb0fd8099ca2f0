#include "hdf5_array.h"

#include <stdexcept>

namespace pumpd::local::hdf5
{
  namespace
  {
    template <class T>
    hid_t type_of();
    template <>
    hid_t type_of<double>() { return H5T_NATIVE_DOUBLE; }
    template <>
    hid_t type_of<std::uint64_t>() { return H5T_NATIVE_UINT64; }
  } // namespace

  template <class T>
  void write_array(hid_t file, const std::string &name, const std::vector<T> &values, const std::string &context)
  {
    const hsize_t n     = values.size();
    const hid_t   space = H5Screate_simple(1, &n, nullptr);
    const hid_t   set   = H5Dcreate2(file, name.c_str(), type_of<T>(), space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const bool    bad =
      set < 0 || (n > 0 && H5Dwrite(set, type_of<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0);
    if (set >= 0)
      H5Dclose(set);
    H5Sclose(space);
    if (bad)
      throw std::runtime_error(context + ": cannot write " + name);
  }

  template <class T>
  std::vector<T> read_array(hid_t file, const std::string &name, const std::string &context, std::size_t expected)
  {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    if (set < 0)
      throw std::runtime_error(context + ": no dataset " + name);
    const hid_t space = H5Dget_space(set);
    hsize_t     n     = 0;
    H5Sget_simple_extent_dims(space, &n, nullptr);
    H5Sclose(space);
    if (expected != any_size && n != expected)
      {
        H5Dclose(set);
        throw std::runtime_error(context + ": " + name + " has " + std::to_string(n) + " entries, expected " +
                                 std::to_string(expected));
      }
    std::vector<T> values(n);
    const bool     bad = n > 0 && H5Dread(set, type_of<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0;
    H5Dclose(set);
    if (bad)
      throw std::runtime_error(context + ": cannot read " + name);
    return values;
  }

  template void write_array(hid_t, const std::string &, const std::vector<double> &, const std::string &);
  template void write_array(hid_t, const std::string &, const std::vector<std::uint64_t> &, const std::string &);
  template std::vector<double> read_array(hid_t, const std::string &, const std::string &, std::size_t);
  template std::vector<std::uint64_t> read_array(hid_t, const std::string &, const std::string &, std::size_t);
} // namespace pumpd::local::hdf5
