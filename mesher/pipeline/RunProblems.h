#pragma once
// The problems of a run by CAD entity (mesher/core/Problem.h), named 1-based with the part
// (solid) they belong to: the model's defects graded, the faces the surface mesher could
// not mesh, the solids the volume mesher could not.
#include <string>
#include <vector>

#include "mesher/core/Problem.h"
#include "mesher/model/Model.h"
#include "mesher/pipeline/SurfaceMesher.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso {

/// The name of the first solid whose shells use each face ("" for a face of no solid).
std::vector<std::string> facePartNames(const Model& model);

/// Model::check() graded: a loop gap is Degraded ("loop-gap", meshed across), an unusable
/// entity Failed ("cad-unusable"), anything else a Note ("cad-defect"); phase "model".
struct ModelGrade {
  std::vector<Problem> problems;
  std::vector<char> skipFaces;  ///< one flag per face: unusable, or bounded by an unusable edge
  bool usable = true;           ///< false: an unusable solid or shell, or no face left
};
ModelGrade gradeModel(const Model& model);

/// One Failed problem ("face-mesh", phase "surface") per face the surface mesher left out,
/// one Note ("face-collapsed") per face it meshed that the surface repair left without
/// elements, one Note ("refinement-limit") per face whose refinement stopped at its bound.
std::vector<Problem> surfaceProblems(const Model& model, const SurfaceMeshResult& surface);

/// The solids' problems, their part names filled in (phase "volume").
std::vector<Problem> volumeProblems(const Model& model, const VolumeMeshResult& volume);

}  // namespace aniso
