#pragma once
// The writers behind writeSurfaceMesh / writeVolumeMesh (io/MeshWriter.h), one per file.
// Each checks nothing about the extension and writes atomically (io/AtomicFile.h).
#include <string>

#include "io/MeshWriter.h"
#include "io/OutputMesh.h"

namespace aniso::io {

void writeMsh41(const OutputMesh& mesh, const std::string& path, const WriteOptions& options);
void writeMsh22(const OutputMesh& mesh, const std::string& path, const WriteOptions& options);
void writeInp(const OutputMesh& mesh, const std::string& path);
void writeVtu(const OutputMesh& mesh, const std::string& path, const WriteOptions& options);
void writeUnv(const OutputMesh& mesh, const std::string& path);
void writeStl(const OutputMesh& mesh, const std::string& path, const WriteOptions& options);
void writeOpenMeshFormat(const OutputMesh& mesh, const std::string& path, const WriteOptions& options);

/// Gmsh element type numbers (MSH 2.2 and 4.1) of a shape, linear or quadratic.
int gmshElementType(Shape s, bool quadratic);

}  // namespace aniso::io
