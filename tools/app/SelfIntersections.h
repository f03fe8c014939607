#pragma once
// Solids whose faces cross one another, rebuilt only when meshing needs it. The check
// (cad::PrepareOptions::checkSelfIntersections: BOPAlgo_ArgumentAnalyzer, seconds per
// curved solid) is not run at preparation: the volume mesher finds such a solid itself, its
// boundary mesh crossing itself (mesher/volume/BoundaryCrossing.h), and leaves it out with
// problems coded "boundary-self-crossing". Those solids, and only those, are then checked
// and rebuilt from their faces, and the model meshed again, once.
#include <vector>

#include "mesher/pipeline/MeshResult.h"
#include "tools/app/ModelInput.h"

namespace aniso::app {

/// The solids (1-based, in increasing order) a volume mesh left out because their boundary
/// mesh crosses itself (problem code "boundary-self-crossing").
std::vector<int> selfCrossingSolids(const MeshResult& result);

/// Prepares the CAD input `in` again (prepareModel) with `solids` (1-based, as in.model
/// numbers them) checked for faces crossing one another and rebuilt; its times get
/// "prepare again" and "topology again", its report the solids checked. True when one was
/// rebuilt: in.model is then the new model (the pieces of a rebuilt solid take its place,
/// the solids after it may be numbered further on; the preparation's warning names them).
/// False: nothing rebuilt (the same model again), or an analytic model (nothing done).
bool rebuildSelfIntersecting(ModelInput& in, const std::string& file, const std::vector<int>& solids);

}  // namespace aniso::app
