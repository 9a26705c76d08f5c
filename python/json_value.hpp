#pragma once
// Python values as the JSON documents the library reads (the probes' descriptions, scenes given
// as dictionaries).

#include <pybind11/pybind11.h>

#include <string>

#include "sqdem/probe/json_input.hpp"

namespace sqdem::python {

/// A Python value as JSON: dict (string keys), list, tuple, str, bool, int, float, None, and
/// NumPy arrays and scalars (through tolist()). Numbers are kept exactly, NaN and inf too (the
/// library's checks then name their key); TypeError for anything else, ValueError for nesting
/// deeper than 64 levels (a list or dictionary that contains itself).
probe::json toJson(const pybind11::handle& value, const std::string& where);

}  // namespace sqdem::python
