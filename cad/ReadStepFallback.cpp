// The fallback rungs of the STEP reader (ReadStep.cpp): no XCAF document, no part names.
// OCCT 7.6 on Linux raises a caught signal through Standard_ErrorHandler (its handler
// aborts when none is on the stack): OCC_CATCH_SIGNALS must expand to one, so the macro
// that enables it is defined before the header.
#define OCC_CONVERT_SIGNALS
#include <algorithm>
#include <vector>

#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <OSD.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <StepShape_Face.hxx>
#include <StepShape_ManifoldSolidBrep.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>

#include "cad/detail/ChildProcess.h"
#include "cad/detail/Readers.h"
#include "mesher/core/FileExtension.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {
std::string lostSolids(XSControl_Reader& reader, TopoDS_Shape& shape, int* notRebuilt) {
  const Handle(StepData_StepModel) model = Handle(StepData_StepModel)::DownCast(reader.Model());
  if (model.IsNull()) return {};
  int breps = 0;
  for (int i = 1; i <= model->NbEntities(); ++i)
    if (model->Value(i)->IsKind(STANDARD_TYPE(StepShape_ManifoldSolidBrep))) ++breps;
  TopTools_IndexedMapOfShape solids, distinct;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  for (int i = 1; i <= solids.Extent(); ++i) distinct.Add(solids(i).Located(TopLoc_Location()));
  if (distinct.Extent() >= breps) return {};
  const int lost = breps - distinct.Extent();
  const int rebuilt = rebuildLostSolids(shape, lost);
  if (notRebuilt) *notRebuilt = lost - rebuilt;
  const std::string of = " of " + std::to_string(breps) + " solid(s)";
  std::string message;
  if (rebuilt > 0)
    message = std::to_string(rebuilt) + of +
              " came out of the STEP transfer as faces only (the file bounds them with an open shell); "
              "rebuilt as solid(s) from their faces, which close";
  if (rebuilt < lost)
    message += (message.empty() ? "" : "; ") + std::to_string(lost - rebuilt) + of +
               " could not be transferred (their faces, if any were read, are meshed as surfaces: no "
               "tetrahedra inside)";
  return message;
}

int stepFaceCount(XSControl_Reader& reader) {
  const Handle(StepData_StepModel) model = Handle(StepData_StepModel)::DownCast(reader.Model());
  if (model.IsNull()) return 0;
  int faces = 0;
  for (int i = 1; i <= model->NbEntities(); ++i)
    if (model->Value(i)->IsKind(STANDARD_TYPE(StepShape_Face))) ++faces;
  return faces;
}

std::string stepFileUnit(STEPControl_Reader& reader) {
  TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
  reader.FileUnits(lengths, angles, solidAngles);
  std::vector<std::string> names;
  for (int i = 1; i <= lengths.Length(); ++i) {
    const std::string n = lowerCase(lengths.Value(i).ToCString());
    if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string readStepPlain(CadModel::Impl& impl) {
  STEPControl_Reader reader;
  loadStepFile(reader, impl.path);
  testCrashPoint("reader-plain");
  if (reader.TransferRoots() == 0 || reader.NbShapes() == 0)
    throw InputError(impl.path + ": STEP file has no shape OpenCASCADE can transfer");
  impl.shape = reader.OneShape();
  impl.facesInFile = stepFaceCount(reader);
  impl.fileUnit = stepFileUnit(reader);
  return lostSolids(reader, impl.shape, &impl.solidsLost);
}

std::string readStepRoots(CadModel::Impl& impl) {
  OSD::SetSignal(false);  // this process only: a kernel crash becomes OSD_SIGSEGV
  STEPControl_Reader reader;
  loadStepFile(reader, impl.path);
  const int n = reader.NbRootsForTransfer();
  std::string skipped;
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  int kept = 0;
  for (int k = 1; k <= n; ++k) {
    try {
      OCC_CATCH_SIGNALS
      if (k == 1) testCrashPoint("reader-root");
      reader.ClearShapes();
      if (reader.TransferRoot(k) && reader.NbShapes() > 0) {
        b.Add(c, reader.OneShape());
        ++kept;
        continue;
      }
    } catch (const Standard_Failure&) {
    }
    skipped += (skipped.empty() ? "" : ", ") + std::to_string(k);
  }
  if (kept == 0) throw MeshingError("no root of " + std::to_string(n) + " could be transferred");
  impl.shape = kept == 1 && n == 1 ? TopoDS_Shape(reader.OneShape()) : TopoDS_Shape(c);
  impl.facesInFile = stepFaceCount(reader);
  impl.fileUnit = stepFileUnit(reader);
  const std::string lost = lostSolids(reader, impl.shape, &impl.solidsLost);
  if (skipped.empty()) return lost;
  return "skipped root(s) " + skipped + " of " + std::to_string(n) + (lost.empty() ? std::string() : "; " + lost);
}

}  // namespace aniso::cad::detail
