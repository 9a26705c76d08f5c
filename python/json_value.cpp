#include "json_value.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

/// Deeper than any document the library reads: a list or dictionary that contains itself.
constexpr int deepest = 64;

probe::json converted(const py::handle& value, const std::string& where, int depth) {
  if (depth > deepest) {
    throw py::value_error(where + ": nested deeper than " + std::to_string(deepest) + " levels (a list or dictionary that contains itself?)");
  }
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    try {
      return value.cast<long long>();
    } catch (const py::cast_error&) {
      return value.cast<double>();  // beyond 64 bits
    }
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    probe::json object = probe::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw py::type_error(where + ": keys are strings, not " + std::string(py::str(key.get_type())));
      const std::string name = key.cast<std::string>();
      object[name] = converted(item, where + "." + name, depth + 1);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    probe::json array = probe::json::array();
    std::size_t k = 0;
    for (const auto& item : value) array.push_back(converted(item, where + "[" + std::to_string(k++) + "]", depth + 1));
    return array;
  }
  if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype")) return converted(value.attr("tolist")(), where, depth + 1);
  throw py::type_error(where + ": a value of type " + std::string(py::str(value.get_type())) + " cannot be given");
}

}  // namespace

probe::json toJson(const py::handle& value, const std::string& where) { return converted(value, where, 0); }

}  // namespace sqdem::python
