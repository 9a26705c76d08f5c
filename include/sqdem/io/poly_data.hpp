#pragma once
// A VTK polygonal data set described without VTK's headers, so that the code gathering the
// engine's output does not include them: points, one kind of cell (vertices, lines or polygons)
// and named arrays on the points and on the cells. vtk_xml.hpp writes it as a .vtp file.

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem {

/// A named array of tuples, stored flat (tuple by tuple) in the type it is written as.
struct DataArray {
  std::string name;
  int components = 1;
  std::variant<std::vector<double>, std::vector<float>, std::vector<std::int64_t>, std::vector<std::int32_t>, std::vector<std::uint8_t>> values;

  /// Appends `times` tuples of Vec3 (components 3) or of one number (components 1), converted to
  /// the array's type.
  void push(const Vec3& v, std::size_t times = 1) {
    std::visit([&](auto& a) {
      const std::array tuple{cast(a, v.x()), cast(a, v.y()), cast(a, v.z())};
      for (std::size_t k = 0; k < times; ++k) a.insert(a.end(), tuple.begin(), tuple.end());
    }, values);
  }
  void push(double x, std::size_t times = 1) { std::visit([&](auto& a) { a.insert(a.end(), times, cast(a, x)); }, values); }
  /// Room for `tuples` tuples (a frame of 10^5 surfaces: no re-allocation while it is filled).
  void reserve(std::size_t tuples) { std::visit([&](auto& a) { a.reserve(tuples * components); }, values); }

 private:
  template <typename Vector>
  static typename Vector::value_type cast(const Vector&, double x) { return static_cast<typename Vector::value_type>(x); }
};

struct PolyData {
  enum class Cells { Vertices, Lines, Polygons };
  DataArray points{"Points", 3, std::vector<double>{}};  ///< x y z per point (m)
  Cells cells = Cells::Vertices;
  std::vector<std::int64_t> offsets;       ///< end of each cell in connectivity
  std::vector<std::int64_t> connectivity;  ///< the cells' point indices
  std::vector<DataArray> pointData, cellData;
  std::string pointScalars, cellScalars;   ///< the arrays ParaView colours by when the file opens

  std::size_t pointCount() const { return std::visit([](const auto& a) { return a.size(); }, points.values) / 3; }
  /// Closes a cell made of the points pushed to connectivity since the last one.
  void endCell() { offsets.push_back(static_cast<std::int64_t>(connectivity.size())); }
};

}  // namespace sqdem
