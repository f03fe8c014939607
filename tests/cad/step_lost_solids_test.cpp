// lostSolids (cad/detail/Readers.h): the solid B-reps a STEP file declares against the solids
// a transfer gave; the readers turn a loss into a warning (a solid OCCT drops, or builds only
// as faces, must not vanish silently).
#include <BRep_Builder.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Compound.hxx>
#include <gtest/gtest.h>

#include <string>

#include "cad/detail/Readers.h"

namespace aniso::cad::detail {
namespace {

const std::string kModels = std::string(ANISOMESH_SOURCE_DIR) + "/models/";

TEST(LostSolids, CountsTheSolidBrepsTheShapeLacks) {
  STEPControl_Reader reader;
  loadStepFile(reader, kModels + "bracket.step");
  ASSERT_GT(reader.TransferRoots(), 0);
  EXPECT_EQ(lostSolids(reader, reader.OneShape()), "");
  TopoDS_Compound nothing;
  BRep_Builder().MakeCompound(nothing);
  EXPECT_EQ(lostSolids(reader, nothing), "1 of 1 solid(s) could not be transferred");
}

}  // namespace
}  // namespace aniso::cad::detail
