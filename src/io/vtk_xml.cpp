#include "sqdem/io/vtk_xml.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>

namespace sqdem {
namespace {

template <typename T> struct VtkArrayOf;
template <> struct VtkArrayOf<double> { using type = vtkDoubleArray; };
template <> struct VtkArrayOf<float> { using type = vtkFloatArray; };
template <> struct VtkArrayOf<std::int64_t> { using type = vtkTypeInt64Array; };
template <> struct VtkArrayOf<std::int32_t> { using type = vtkIntArray; };

vtkSmartPointer<vtkDataArray> toVtk(const DataArray& array) {
  return std::visit(
      [&](const auto& values) -> vtkSmartPointer<vtkDataArray> {
        using Value = typename std::decay_t<decltype(values)>::value_type;
        auto out = vtkSmartPointer<typename VtkArrayOf<Value>::type>::New();
        out->SetName(array.name.c_str());
        out->SetNumberOfComponents(array.components);
        out->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / array.components));
        std::copy(values.begin(), values.end(), out->GetPointer(0));
        return out;
      },
      array.values);
}

/// The cells in 32-bit indices when they fit (half the file's connectivity), else 64-bit.
template <typename IndexArray>
vtkSmartPointer<vtkCellArray> cellsAs(const PolyData& data) {
  vtkNew<IndexArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(data.offsets.size() + 1));
  offsets->SetValue(0, 0);
  std::copy(data.offsets.begin(), data.offsets.end(), offsets->GetPointer(1));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(data.connectivity.size()));
  std::copy(data.connectivity.begin(), data.connectivity.end(), connectivity->GetPointer(0));
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->SetData(offsets, connectivity);
  return out;
}

vtkSmartPointer<vtkCellArray> cells(const PolyData& data) {
  constexpr std::size_t int32Limit = 2147483647;
  return data.connectivity.size() < int32Limit ? cellsAs<vtkTypeInt32Array>(data) : cellsAs<vtkTypeInt64Array>(data);
}

}  // namespace

std::string vtkXml(const PolyData& data) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetData(toVtk(data.points));
  poly->SetPoints(points);
  switch (data.cells) {
    case PolyData::Cells::Vertices: poly->SetVerts(cells(data)); break;
    case PolyData::Cells::Lines: poly->SetLines(cells(data)); break;
    case PolyData::Cells::Polygons: poly->SetPolys(cells(data)); break;
  }
  for (const DataArray& a : data.pointData) poly->GetPointData()->AddArray(toVtk(a));
  for (const DataArray& a : data.cellData) poly->GetCellData()->AddArray(toVtk(a));
  if (!data.pointScalars.empty()) poly->GetPointData()->SetActiveScalars(data.pointScalars.c_str());
  if (!data.cellScalars.empty()) poly->GetCellData()->SetActiveScalars(data.cellScalars.c_str());
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw binary after the XML header
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(1);
  writer->SetHeaderTypeToUInt64();
  writer->WriteToOutputStringOn();
  if (writer->Write() != 1) throw std::runtime_error("VTK could not write a .vtp frame");
  return writer->GetOutputString();
}

}  // namespace sqdem
