#include "sqdem/io/stl_mesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace sqdem {

StlMesh readStlMesh(const std::filesystem::path& path, double scale) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw MeshError(path.string() + ": cannot open the STL file");
  if (!CGAL::IO::read_STL(path.string(), points, polygons) || polygons.empty()) {
    throw MeshError(path.string() + ": not an STL file with at least one triangle (ASCII 'solid ... endsolid' or binary)");
  }
  StlMesh out;
  MeshRepairs& r = out.repairs;
  r.verticesRead = 3 * polygons.size();
  r.trianglesRead = polygons.size();
  // Zero-area triangles (collinear corners, exact predicate): the soup repair removes only those
  // that repeat a vertex, and a sliver's extra vertex would break the surface's manifoldness.
  std::erase_if(polygons, [&](const std::vector<std::size_t>& t) {
    return t.size() != 3 || CGAL::collinear(points[t[0]], points[t[1]], points[t[2]]);
  });
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty()) throw MeshError(path.string() + ": every triangle is degenerate (zero area)");
  const auto beforeOrienting = polygons;
  PMP::orient_polygon_soup(points, polygons);  // may duplicate a non-manifold vertex to do so
  r.reoriented = polygons != beforeOrienting;

  CGAL::Surface_mesh<Point> mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  r.closed = CGAL::is_closed(mesh);
  if (r.closed) PMP::orient_to_bound_a_volume(mesh);
  r.verticesMerged = r.verticesRead - mesh.number_of_vertices();
  r.trianglesRemoved = r.trianglesRead - mesh.number_of_faces();

  TriangleMesh& m = out.mesh;
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    m.vertices.emplace_back(scale * p.x(), scale * p.y(), scale * p.z());
  }
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    int corner = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[corner++] = static_cast<std::uint32_t>(v.idx());
    m.triangles.push_back(t);
  }
  return out;
}

}  // namespace sqdem
