// IGES and BREP readers.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>

#include <fstream>
#include <mutex>

#include "cad/detail/Readers.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {

void silenceOcctMessages() {
  static std::once_flag once;
  std::call_once(once, [] {
    const Handle(Message_Messenger)& m = Message::DefaultMessenger();
    m->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

void readIges(CadModel::Impl& impl) {
  try {
    IGESControl_Reader reader;
    const IFSelect_ReturnStatus st = reader.ReadFile(impl.path.c_str());
    if (st != IFSelect_RetDone) throw InputError(impl.path + ": not a readable IGES file");
    reader.TransferRoots();
    if (reader.NbShapes() == 0) throw InputError(impl.path + ": IGES file has no shape OpenCASCADE can transfer");
    impl.shape = reader.OneShape();
  } catch (const Standard_Failure& e) {
    throw InputError(impl.path + ": OpenCASCADE failed reading IGES: " + e.GetMessageString());
  }
}

void readBrep(CadModel::Impl& impl) {
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

}  // namespace aniso::cad::detail
