#pragma once
// Read-only NumPy arrays over the library's stores, without a copy: each holds a reference to
// its owner (the Python Simulation), so the memory outlives every view of it while the store
// keeps it; a view is valid until the next step (re-ordering and migration move rows, a rebuild
// reallocates), docs/python.md.

#include <pybind11/numpy.h>

#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem::python {

namespace detail {
/// The array made read-only (NumPy's WRITEABLE flag cleared).
template <typename T>
pybind11::array_t<T> readOnly(pybind11::array_t<T> array) {
  pybind11::detail::array_proxy(array.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}
}  // namespace detail

/// An (n, components) array over the first n records of `values` (`components` doubles each;
/// the particle store keeps its ghosts after its n particles).
template <typename Record>
pybind11::array_t<double> rows(const std::vector<Record>& values, std::size_t n, int components, pybind11::handle owner) {
  static_assert(sizeof(Record) % sizeof(double) == 0);
  return detail::readOnly(pybind11::array_t<double>(
      {static_cast<pybind11::ssize_t>(n), static_cast<pybind11::ssize_t>(components)},
      {static_cast<pybind11::ssize_t>(sizeof(Record)), static_cast<pybind11::ssize_t>(sizeof(double))},
      reinterpret_cast<const double*>(values.data()), owner));
}
template <typename Record>
pybind11::array_t<double> rows(const std::vector<Record>& values, int components, pybind11::handle owner) {
  return rows(values, values.size(), components, owner);
}

/// An (n,) array over the first n values.
template <typename T>
pybind11::array_t<T> column(const std::vector<T>& values, std::size_t n, pybind11::handle owner) {
  return detail::readOnly(pybind11::array_t<T>({static_cast<pybind11::ssize_t>(n)}, {static_cast<pybind11::ssize_t>(sizeof(T))},
                                               values.data(), owner));
}
template <typename T>
pybind11::array_t<T> column(const std::vector<T>& values, pybind11::handle owner) {
  return column(values, values.size(), owner);
}

}  // namespace sqdem::python
