#pragma once
// A VTK image (regular grid of cells) described without VTK's headers, as poly_data.hpp does for
// polygonal data: its cells' count, the grid's origin and spacing, and named arrays on the cells
// (x fastest, then y, then z). vtk_xml.hpp writes it as a .vti file.

#include <array>
#include <vector>

#include "sqdem/io/poly_data.hpp"

namespace sqdem {

struct ImageData {
  std::array<int, 3> cells{0, 0, 0};  ///< along x, y, z
  Vec3 origin = Vec3::Zero();         ///< (m) the low corner
  Vec3 spacing = Vec3::Zero();        ///< (m) a cell's edges
  std::vector<DataArray> cellData;
  std::string cellScalars;            ///< the array ParaView colours by when the file opens
};

}  // namespace sqdem
