#include "io/ControlSpaceVtu.h"

#include <iomanip>
#include <ostream>

#include "io/AtomicFile.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

void tensorArray(std::ostream& o, const char* name, const std::vector<Mat3>& v) {
  o << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"9\" format=\"ascii\">\n";
  for (const Mat3& m : v) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) o << m(r, c) << ' ';
    o << '\n';
  }
  o << "</DataArray>\n";
}

}  // namespace

void writeControlSpaceVtu(const ControlSpaceGrid& g, const std::string& path, const std::vector<int>* cellFace) {
  const size_t np = g.points.size(), nc = g.cellCount();
  if (g.cells.size() != nc * static_cast<size_t>(g.cellSize))
    throw MeshingError(path + ": inconsistent control space grid (cells)");
  const bool hasMetric = !g.metric.empty();
  if (hasMetric && (g.metric.size() != np || g.lengths.size() != np || g.directions.size() != np))
    throw MeshingError(path + ": inconsistent control space grid (metric)");
  AtomicFile f(path);
  std::ostream& o = f.stream();
  o << std::setprecision(12);
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << np << "\" NumberOfCells=\"" << nc << "\">\n";
  o << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : g.points) o << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  o << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (size_t c = 0; c < nc; ++c) {
    for (int k = 0; k < g.cellSize; ++k) o << g.cells[c * g.cellSize + k] << ' ';
    o << '\n';
  }
  o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t c = 1; c <= nc; ++c) o << c * g.cellSize << '\n';
  o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  // (dim, cellSize) → VTK_HEXAHEDRON, VTK_TRIANGLE, VTK_TETRA, VTK_QUAD (ControlSpaceGrid.h)
  const int vtkType = g.cellSize == 8 ? 12 : g.cellSize == 3 ? 5 : g.dim == 3 ? 10 : 9;
  for (size_t c = 0; c < nc; ++c) o << vtkType << '\n';
  o << "</DataArray>\n</Cells>\n<CellData Scalars=\"level\">\n<DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n";
  for (int l : g.cellLevel) o << l << '\n';
  o << "</DataArray>\n";
  if (cellFace) {
    if (cellFace->size() != nc) throw MeshingError(path + ": inconsistent control space grid (faces)");
    o << "<DataArray type=\"Int32\" Name=\"face\" format=\"ascii\">\n";
    for (int f : *cellFace) o << f << '\n';
    o << "</DataArray>\n";
  }
  o << "</CellData>\n";
  if (hasMetric) {
    o << "<PointData Tensors=\"metric\" Scalars=\"h1\">\n";
    tensorArray(o, "metric", g.metric);
    for (int i = 0; i < g.dim; ++i) {
      o << "<DataArray type=\"Float64\" Name=\"h" << i + 1 << "\" format=\"ascii\">\n";
      for (const Vec3& l : g.lengths) o << l[i] << '\n';
      o << "</DataArray>\n";
    }
    for (int i = 0; i < g.dim; ++i) {
      o << "<DataArray type=\"Float64\" Name=\"e" << i + 1 << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const Mat3& d : g.directions) o << d(0, i) << ' ' << d(1, i) << ' ' << d(2, i) << '\n';
      o << "</DataArray>\n";
    }
    if (!g.parameterization.empty()) tensorArray(o, "Mp", g.parameterization);
    o << "</PointData>\n";
  }
  o << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  f.commit();
}

}  // namespace aniso::io
