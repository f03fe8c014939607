// IGES and BREP readers, each in a child process (detail/ChildProcess.h).
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>

#include <fstream>
#include <mutex>

#include "cad/detail/ChildProcess.h"
#include "cad/detail/Readers.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"

namespace aniso::cad::detail {

void silenceOcctMessages() {
  static std::once_flag once;
  std::call_once(once, [] {
    const Handle(Message_Messenger)& m = Message::DefaultMessenger();
    m->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

namespace {

/// Runs a reader in a child process (ChildProcess.h); its InputError passes, a crash or an
/// OCCT failure becomes an InputError naming the format.
void readIsolated(CadModel::Impl& impl, const char* format, void (*reader)(CadModel::Impl&)) {
  const ChildOutcome o = runInChild(impl, "reading", [reader](CadModel::Impl& i) {
    reader(i);
    return std::string();
  });
  if (o.kind == ChildOutcome::Done) return;
  if (o.kind == ChildOutcome::Input) throw InputError(o.message);
  throw InputError(impl.path + ": OpenCASCADE could not read this " + format + " file (" +
                   (o.kind == ChildOutcome::Crashed ? "it crashed in the reader: " : "") + o.message + ")");
}

/// The IGES global section's unit (flag 1-11, IGES 5.3 sec. 2.2.4.3; flag 3 names it).
std::string igesUnit(const IGESData_GlobalSection& g) {
  static const char* const kUnits[] = {"",     "inch",   "millimetre", "",     "foot",      "mile",
                                       "metre", "kilometre", "mil",   "micrometre", "centimetre", "microinch"};
  const int flag = g.UnitFlag();
  if (flag == 3 && !g.UnitName().IsNull()) return lowerCase(g.UnitName()->ToCString());
  return flag >= 1 && flag <= 11 ? kUnits[flag] : "";
}

void readIgesHere(CadModel::Impl& impl) {
  try {
    IGESControl_Reader reader;
    const IFSelect_ReturnStatus st = reader.ReadFile(impl.path.c_str());
    if (st != IFSelect_RetDone) throw InputError(impl.path + ": not a readable IGES file");
    reader.TransferRoots();
    if (reader.NbShapes() == 0) throw InputError(impl.path + ": IGES file has no shape OpenCASCADE can transfer");
    impl.shape = reader.OneShape();
    impl.fileUnit = igesUnit(reader.IGESModel()->GlobalSection());
  } catch (const Standard_Failure& e) {
    throw InputError(impl.path + ": OpenCASCADE failed reading IGES: " + e.GetMessageString());
  }
}

void readBrepHere(CadModel::Impl& impl) {
  try {
    BRep_Builder builder;
    TopoDS_Shape shape;
    std::ifstream in(impl.path, std::ios::binary);
    BRepTools::Read(shape, in, builder);
    if (shape.IsNull()) throw InputError(impl.path + ": not a readable BREP file");
    impl.shape = shape;
  } catch (const Standard_Failure& e) {
    throw InputError(impl.path + ": OpenCASCADE failed reading BREP: " + e.GetMessageString());
  }
}

}  // namespace

void readIges(CadModel::Impl& impl) { readIsolated(impl, "IGES", readIgesHere); }
void readBrep(CadModel::Impl& impl) { readIsolated(impl, "BREP", readBrepHere); }

}  // namespace aniso::cad::detail
