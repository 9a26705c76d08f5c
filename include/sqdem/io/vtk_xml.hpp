#pragma once
// A PolyData (poly_data.hpp) as the text of a VTK XML .vtp file, written by VTK's
// vtkXMLPolyDataWriter: appended raw binary data, zlib-compressed. Own target (sqdem_vtk_io):
// VTK's headers stay in vtk_xml.cpp.

#include <string>

#include "sqdem/io/poly_data.hpp"

namespace sqdem {

std::string vtkXml(const PolyData& data);

}  // namespace sqdem
