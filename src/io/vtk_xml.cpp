#include "sqdem/io/vtk_xml.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkTypeUInt8Array.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPPolyDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>
#include <type_traits>

#include "sqdem/archive/atomic_file.hpp"

namespace sqdem {
namespace {

/// Bytes compressed at a time. zlib sets up its state (a quarter of a megabyte, allocated and
/// cleared) for every block: at VTK's default of 32 KiB that took a third of a frame's write time.
constexpr std::size_t blockSize = std::size_t{1} << 20;

template <typename T> struct VtkArrayOf;
template <> struct VtkArrayOf<double> { using type = vtkDoubleArray; };
template <> struct VtkArrayOf<float> { using type = vtkFloatArray; };
template <> struct VtkArrayOf<std::int64_t> { using type = vtkTypeInt64Array; };
template <> struct VtkArrayOf<std::int32_t> { using type = vtkIntArray; };
template <> struct VtkArrayOf<std::uint8_t> { using type = vtkTypeUInt8Array; };

/// The array read in place (VTK's SetArray with save = 1: neither copied nor freed; a writer only
/// reads it): a frame of 10^5 surfaces holds 10^7 values per array.
vtkSmartPointer<vtkDataArray> toVtk(const DataArray& array) {
  return std::visit(
      [&](const auto& values) -> vtkSmartPointer<vtkDataArray> {
        using Value = typename std::decay_t<decltype(values)>::value_type;
        using Array = typename VtkArrayOf<Value>::type;
        using Stored = typename Array::ValueType;  // vtkTypeInt64 is long long, std::int64_t long
        static_assert(sizeof(Stored) == sizeof(Value) && std::is_integral_v<Stored> == std::is_integral_v<Value>);
        auto out = vtkSmartPointer<Array>::New();
        out->SetName(array.name.c_str());
        out->SetNumberOfComponents(array.components);
        out->SetArray(reinterpret_cast<Stored*>(const_cast<Value*>(values.data())), static_cast<vtkIdType>(values.size()), 1);
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

vtkSmartPointer<vtkPolyData> toVtk(const PolyData& data) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
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
  return poly;
}

/// The output's encoding: appended raw binary after the XML header, compressed in blocks (zlib at
/// level 1, LZ4 at its default, or none), 64-bit headers.
template <typename Writer>
void encode(Writer& writer, VtkCompression compression) {
  writer.SetDataModeToAppended();
  writer.EncodeAppendedDataOff();
  switch (compression) {
    case VtkCompression::ZLib:
      writer.SetCompressorTypeToZLib();
      writer.SetCompressionLevel(1);
      break;
    case VtkCompression::LZ4: writer.SetCompressorTypeToLZ4(); break;
    case VtkCompression::None: writer.SetCompressorTypeToNone(); break;
  }
  writer.SetBlockSize(blockSize);
  writer.SetHeaderTypeToUInt64();
}

}  // namespace

void writeVtp(const PolyData& data, const std::filesystem::path& file, VtkCompression compression) {
  writeFileAtomically(file, [&](const std::filesystem::path& temporary) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(toVtk(data));
    encode(*writer, compression);
    writer->SetFileName(temporary.string().c_str());
    if (writer->Write() != 1) throw std::runtime_error("VTK could not write '" + file.string() + "'");
  });
}

void writeVti(const ImageData& data, const std::filesystem::path& file, VtkCompression compression) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(data.cells[0] + 1, data.cells[1] + 1, data.cells[2] + 1);  // points
  image->SetOrigin(data.origin.x(), data.origin.y(), data.origin.z());
  image->SetSpacing(data.spacing.x(), data.spacing.y(), data.spacing.z());
  for (const DataArray& a : data.cellData) image->GetCellData()->AddArray(toVtk(a));
  if (!data.cellScalars.empty()) image->GetCellData()->SetActiveScalars(data.cellScalars.c_str());
  writeFileAtomically(file, [&](const std::filesystem::path& temporary) {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    encode(*writer, compression);
    writer->SetFileName(temporary.string().c_str());
    if (writer->Write() != 1) throw std::runtime_error("VTK could not write '" + file.string() + "'");
  });
}

void writeVtkPiece(const PolyData& data, const std::filesystem::path& summary, int piece, int pieces,
                   VtkCompression compression) {
  vtkNew<vtkXMLPPolyDataWriter> writer;
  writer->SetInputData(toVtk(data));
  encode(*writer, compression);
  writer->SetFileName(summary.string().c_str());
  writer->SetNumberOfPieces(pieces);
  writer->SetStartPiece(piece);
  writer->SetEndPiece(piece);
  // Every rank takes part in the summary (a collective: the ranks tell each other which pieces
  // were written, so that it lists them all); rank 0 writes it.
  // MPI is initialised by the run (distributed/mpi_communicator.hpp): VTK's controller,
  // initialised once, is told so.
  writer->SetWriteSummaryFile(1);
  static const bool initialised = [] {
    vtkNew<vtkMPIController> first;
    first->Initialize(nullptr, nullptr, 1);
    return true;
  }();
  (void)initialised;
  vtkNew<vtkMPIController> controller;
  writer->SetController(controller);
  if (writer->Write() != 1) throw std::runtime_error("VTK could not write piece " + std::to_string(piece) + " of " + summary.string());
}

}  // namespace sqdem
