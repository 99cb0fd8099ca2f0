// One-dimensional HDF5 datasets of doubles or 64-bit unsigned integers, shared by the PD
// checkpoint (checkpoint.h) and the global-local cycle's (coupling/cycle_checkpoint.h). Each
// function throws std::runtime_error whose message starts with `context` ("checkpoint", ...).
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pumpd::local::hdf5
{
  constexpr std::size_t any_size = std::numeric_limits<std::size_t>::max();

  /// T is double or std::uint64_t.
  template <class T>
  void write_array(hid_t file, const std::string &name, const std::vector<T> &values, const std::string &context);

  /// The dataset `name`; if expected is not any_size, a dataset of another length is refused
  /// ("<name> has n entries, expected m").
  template <class T>
  std::vector<T> read_array(hid_t file, const std::string &name, const std::string &context,
                            std::size_t expected = any_size);
} // namespace pumpd::local::hdf5
