#pragma once
// A PolyData (poly_data.hpp) as a VTK XML .vtp file, written (atomically) by VTK's
// vtkXMLPolyDataWriter: appended raw binary data, compressed (VtkCompression); across ranks a piece per rank
// and a .pvtp, by vtkXMLPPolyDataWriter. Own target (sqdem_vtk_io):
// VTK's headers stay in vtk_xml.cpp.

#include <filesystem>

#include "sqdem/io/image_data.hpp"
#include "sqdem/io/poly_data.hpp"

namespace sqdem {

/// How the arrays are compressed (VTK's compressors; every VTK-based reader, ParaView among
/// them, reads all three): timings and sizes in docs/output.md.
enum class VtkCompression {
  ZLib,  ///< level 1: the smallest files, read by any VTK XML reader
  LZ4,   ///< ~2x faster to write, ~1.7x larger
  None,  ///< raw
};

/// Throws std::runtime_error naming the file.
void writeVtp(const PolyData& data, const std::filesystem::path& file, VtkCompression compression);

/// An ImageData as a VTK XML .vti file (vtkXMLImageDataWriter, the same encoding), atomically.
/// Throws std::runtime_error naming the file.
void writeVti(const ImageData& data, const std::filesystem::path& file, VtkCompression compression);

/// Piece `piece` of `pieces` of a frame (a rank's share), written with the same encoding by VTK's
/// parallel writer (vtkXMLPPolyDataWriter) as `<stem>_<piece>.vtp` beside `summary`, the .pvtp
/// that lists the pieces, which the writer of piece 0 writes too. Throws std::runtime_error.
void writeVtkPiece(const PolyData& data, const std::filesystem::path& summary, int piece, int pieces,
                   VtkCompression compression);

}  // namespace sqdem
