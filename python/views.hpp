#pragma once
// NumPy arrays over the library's stores, without a copy: each holds a reference to its owner
// (the Python Simulation), so the memory outlives every view of it; a view is valid until the
// next step (re-ordering and migration move rows, a rebuild reallocates), docs/python.md.

#include <pybind11/numpy.h>

#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem::python {

/// An (n, components) array over the first n records of `values` (`components` doubles each;
/// the particle store keeps its ghosts after its n particles).
template <typename Record>
pybind11::array_t<double> rows(std::vector<Record>& values, std::size_t n, int components, pybind11::handle owner, bool writable) {
  static_assert(sizeof(Record) % sizeof(double) == 0);
  pybind11::array_t<double> out({static_cast<pybind11::ssize_t>(n), static_cast<pybind11::ssize_t>(components)},
                                {static_cast<pybind11::ssize_t>(sizeof(Record)), static_cast<pybind11::ssize_t>(sizeof(double))},
                                reinterpret_cast<double*>(values.data()), owner);
  if (!writable) pybind11::detail::array_proxy(out.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}
/// A read-only one over a store the library gives as const.
template <typename Record>
pybind11::array_t<double> rows(const std::vector<Record>& values, int components, pybind11::handle owner) {
  return rows(const_cast<std::vector<Record>&>(values), values.size(), components, owner, false);
}

/// An (n,) array over the first n values.
template <typename T>
pybind11::array_t<T> column(std::vector<T>& values, std::size_t n, pybind11::handle owner, bool writable) {
  pybind11::array_t<T> out({static_cast<pybind11::ssize_t>(n)}, {static_cast<pybind11::ssize_t>(sizeof(T))},
                           values.data(), owner);
  if (!writable) pybind11::detail::array_proxy(out.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}
/// A read-only one over a store the library gives as const.
template <typename T>
pybind11::array_t<T> column(const std::vector<T>& values, pybind11::handle owner) {
  return column(const_cast<std::vector<T>&>(values), values.size(), owner, false);
}

}  // namespace sqdem::python
