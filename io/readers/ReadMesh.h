#pragma once
// ReadMesh — a mesh as read from a file, whatever wrote it: nodes, elements of any of the
// common linear and quadratic types, and named groups of elements. What `anisomesh check`
// analyses (MeshCheck.h).
//
// Element nodes are 0-based indices into `nodes`, in our canonical order for the types we
// write (corners, then mid-edge nodes in the data contracts' edge order: triangle (0,1)
// (1,2) (2,0); quad (0,1) (1,2) (2,3) (3,0); tetrahedron VolumeMesh::kTetEdges); each reader
// permutes its format's order to it (Gmsh's tet10 swaps its last two nodes). Other types
// keep their format's order (they are counted, not checked).
//
// Readers, one per format (the format from the extension, any case):
//   .msh  Gmsh 4.1 ASCII and binary, 2.2 ASCII and binary; groups: the physical groups
//         (named from $PhysicalNames, else "<dim>:<tag>")
//   .inp  Abaqus / CalculiX: *NODE, *ELEMENT (TYPE=C3D4 C3D10 S3 S6 S4 S8 CPS3 ... with
//         ELSET=), *ELSET, *NSET (GENERATE too), *INCLUDE; groups: the element sets
//   .vtu  VTK XML unstructured grid, ASCII, inline base64 ("binary") or appended (raw or
//         base64), uncompressed or zlib (VtuPayload.h); groups: "<array>=<value>" for each integer cell-data array
//   .stl .obj .off  through OpenMesh's readers (polygon soup: no faces are dropped)
//   .frd  CalculiX results (ASCII): nodes, elements and the last step's nodal results
//         (io/readers/fields/FrdReader.cpp)
// Data arrays (pointData, cellData): MSH $NodeData / $ElementData (the last time step of
// each name), VTU PointData / CellData, FRD result blocks. A node or element the file gives
// no value for holds NaN.
// Every reader throws InputError naming the file for a missing, unreadable, truncated or
// malformed file, or a file that holds no element.
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso::io {

enum class CellType : std::uint8_t {
  Point, Line, Line3, Triangle, Triangle6, Quad, Quad8, Quad9,
  Tet, Tet10, Hex, Hex20, Hex27, Prism, Prism15, Prism18, Pyramid, Pyramid13, Pyramid14,
  Polygon,  ///< a face with more than four corners (OBJ/OFF)
};

/// Short lower-case name ("triangle6", "tet10", ...), used in reports.
const char* cellTypeName(CellType t);
/// Dimension of the type: 0 point, 1 line, 2 face, 3 solid.
int cellDimension(CellType t);
/// Number of nodes (0 for Polygon: any).
int cellNodeCount(CellType t);

struct MeshGroup {
  std::string name;
  std::vector<int> cells;  ///< 0-based element indices, increasing
};

struct NodeSet {
  std::string name;
  std::vector<int> nodes;  ///< 0-based node indices, increasing
};

/// A named data array: `components` values per node (or per element), node-major.
struct MeshData {
  std::string name;
  int components = 1;
  std::vector<std::string> componentNames;  ///< FRD: D1 D2 D3, SXX ...; else empty
  std::vector<double> values;               ///< size = count × components
};

struct ReadMesh {
  std::string format;  ///< "msh4.1 ascii", "inp", "vtu", "stl", ...
  std::vector<Vec3> nodes;
  std::vector<CellType> types;
  std::vector<int> offsets{0};  ///< element i: conn[offsets[i] .. offsets[i+1])
  std::vector<int> conn;
  std::vector<MeshGroup> groups;
  std::vector<NodeSet> nodeSets;  ///< INP *NSET
  std::vector<MeshData> pointData;  ///< per node
  std::vector<MeshData> cellData;   ///< per element

  std::size_t cellCount() const { return types.size(); }
  int cellSize(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  const int* cell(std::size_t i) const { return conn.data() + offsets[i]; }
  void addCell(CellType t, const int* n, int count) {
    types.push_back(t);
    conn.insert(conn.end(), n, n + count);
    offsets.push_back(static_cast<int>(conn.size()));
  }
};

/// Reads any supported format, chosen by the extension. Throws InputError.
ReadMesh readMesh(const std::string& path);

ReadMesh readMsh(const std::string& path);
ReadMesh readInp(const std::string& path);
ReadMesh readVtu(const std::string& path);
ReadMesh readSurfaceWithOpenMesh(const std::string& path);
ReadMesh readFrd(const std::string& path);

}  // namespace aniso::io
