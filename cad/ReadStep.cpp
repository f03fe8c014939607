// STEP AP203/214/242 through XCAF, so that each solid keeps the name and colour of its part
// and each face its own name and colour (sub-shape labels), in a child process (detail/ChildProcess.h); when OCCT crashes or fails there, the plain reader
// and then the root-by-root reader (ReadStepFallback.cpp) are tried.
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_ChildIterator.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <BRep_Builder.hxx>
#include <XCAFApp_Application.hxx>
#include <Quantity_Color.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include "cad/detail/ChildProcess.h"
#include "cad/detail/Readers.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {
namespace {

std::string labelName(const TDF_Label& label) {
  Handle(TDataStd_Name) attr;
  if (!label.FindAttribute(TDataStd_Name::GetID(), attr)) return {};
  TCollection_AsciiString s(attr->Get());
  std::string name = s.ToCString();
  // Trim; STEP writers often leave empty or whitespace names.
  const auto b = name.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return name.substr(b, name.find_last_not_of(" \t") - b + 1);
}

/// The colour XCAF attaches to the label itself (surface colour first, then the generic
/// one) as "#rrggbb", "" when none: never one inherited from a parent label.
std::string labelColor(const Handle(XCAFDoc_ColorTool)& colors, const TDF_Label& label) {
  Quantity_Color c;
  if (!colors->GetColor(label, XCAFDoc_ColorSurf, c) && !colors->GetColor(label, XCAFDoc_ColorGen, c)) return {};
  std::string hex = Quantity_Color::ColorToHex(c).ToCString();
  for (char& ch : hex) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return hex;
}

/// A face name that says nothing: "NONE", or a STEP entity reference ("#441": some
/// exporters name every face after its own entity, as in as1-tu-203.stp, where the
/// faces of every nut would otherwise share the groups "#197", "#209", ...).
bool placeholderFaceName(const std::string& name) {
  if (name == "NONE") return true;
  return name.size() > 1 && name[0] == '#' &&
         std::all_of(name.begin() + 1, name.end(), [](unsigned char c) { return std::isdigit(c); });
}

/// Records the name and colour of every face sub-shape label of a part: what the file
/// says of the face itself (a sub-shape that is a shell or a solid names no face; a
/// placeholder name is no name).
void collectFaceTags(const TDF_Label& part, const Handle(XCAFDoc_ColorTool)& colors, CadModel::Impl& impl) {
  TDF_LabelSequence subs;
  XCAFDoc_ShapeTool::GetSubShapes(part, subs);
  for (int i = 1; i <= subs.Length(); ++i) {
    const TopoDS_Shape face = XCAFDoc_ShapeTool::GetShape(subs.Value(i));
    if (face.IsNull() || face.ShapeType() != TopAbs_FACE) continue;
    FaceTag tag{labelName(subs.Value(i)), labelColor(colors, subs.Value(i))};
    if (placeholderFaceName(tag.name)) tag.name.clear();
    const TopoDS_Shape key = face.Located(TopLoc_Location());
    if ((tag.name.empty() && tag.color.empty()) || impl.faceTagIndex.IsBound(key)) continue;
    impl.faceTags.push_back(std::move(tag));
    impl.faceTagIndex.Bind(key, static_cast<int>(impl.faceTags.size()) - 1);
  }
}

/// Records the part name and colour of every solid of every simple-shape label (parts,
/// not assemblies), keyed by the solid without its location so that every instance of a
/// part finds them, and the tags of the parts' faces.
void collectPartNames(const Handle(XCAFDoc_ShapeTool)& tool, const Handle(XCAFDoc_ColorTool)& colors,
                      CadModel::Impl& impl) {
  TDF_LabelSequence labels;
  tool->GetShapes(labels);
  for (int i = 1; i <= labels.Length(); ++i) {
    const TDF_Label& label = labels.Value(i);
    if (XCAFDoc_ShapeTool::IsAssembly(label)) continue;
    collectFaceTags(label, colors, impl);
    const std::string name = labelName(label), color = labelColor(colors, label);
    if (name.empty() && color.empty()) continue;
    TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(shape, TopAbs_SOLID, solids);
    for (int k = 1; k <= solids.Extent(); ++k) {
      TopoDS_Shape key = solids(k).Located(TopLoc_Location());
      if (impl.nameIndex.IsBound(key)) continue;
      impl.names.push_back(name);
      impl.partColors.push_back(color);
      impl.nameIndex.Bind(key, static_cast<int>(impl.names.size()) - 1);
    }
  }
}

/// A Part 21 file ends with END-ISO-10303-21; a file cut short (a failed download, a full
/// disk) does not, and OCCT would read what it can without saying so.
bool hasStepTerminator(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff tail = std::min<std::streamoff>(size, 4096);
  in.seekg(size - tail);
  std::string buf(static_cast<size_t>(tail), '\0');
  in.read(buf.data(), tail);
  return buf.find("END-ISO-10303-21") != std::string::npos;
}

}  // namespace

void loadStepFile(XSControl_Reader& reader, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[3] = {0, 0, 0};
  in.read(head, 3);
  IFSelect_ReturnStatus st;
  if (in.gcount() == 3 && head[0] == '\xEF' && head[1] == '\xBB' && head[2] == '\xBF') {
    st = reader.ReadStream(path.c_str(), in);  // the stream stands past the mark
  } else {
    in.close();
    st = reader.ReadFile(path.c_str());
  }
  if (st == IFSelect_RetDone) return;
  // why, in plain words: a missing section, else the parser's refusal of the syntax
  std::ifstream again(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  const char* why = text.find("HEADER;") == std::string::npos ? "it has no HEADER section"
                    : text.find("DATA;") == std::string::npos
                        ? "it has no DATA section"
                        : "OpenCASCADE's parser rejected its syntax (ISO 10303-21)";
  throw InputError(path + ": not a readable STEP file: " + why);
}

std::string readStepXcaf(CadModel::Impl& impl) {
  try {
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    // named faces become sub-shape labels (STEP representation items' names)
    Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
    reader.SetLayerMode(false);
    try {
      loadStepFile(reader.ChangeReader(), impl.path);
    } catch (const InputError&) {
      app->Close(doc);
      throw;
    }
    testCrashPoint("reader-xcaf");
    if (!reader.Transfer(doc)) {
      app->Close(doc);
      throw InputError(impl.path + ": STEP file has no shape OpenCASCADE can transfer");
    }
    Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence free;
    tool->GetFreeShapes(free);
    if (free.Length() == 1) {
      impl.shape = XCAFDoc_ShapeTool::GetShape(free.Value(1));
    } else {
      TopoDS_Compound c;
      BRep_Builder b;
      b.MakeCompound(c);
      for (int i = 1; i <= free.Length(); ++i) b.Add(c, XCAFDoc_ShapeTool::GetShape(free.Value(i)));
      impl.shape = c;
    }
    collectPartNames(tool, XCAFDoc_DocumentTool::ColorTool(doc->Main()), impl);
    impl.facesInFile = stepFaceCount(reader.ChangeReader());
    impl.fileUnit = stepFileUnit(reader.ChangeReader());
    std::string lost = lostSolids(reader.ChangeReader(), impl.shape, &impl.solidsLost);
    app->Close(doc);
    return lost;
  } catch (const Standard_Failure& e) {  // for the next rung: the child reports it as failed
    throw MeshingError(std::string("OpenCASCADE failed in the XCAF reader: ") + e.GetMessageString());
  }
}

namespace {

/// Why a reader path failed, for the warning or the final message.
std::string failure(const ChildOutcome& o) {
  return o.kind == ChildOutcome::Crashed ? "crashed: " + o.message : o.message;
}

}  // namespace

void readStep(CadModel::Impl& impl) {
  if (!hasStepTerminator(impl.path))
    throw InputError(impl.path + ": STEP file is truncated (no END-ISO-10303-21)");
  // 1: XCAF, with part names. Its refusals (not STEP, nothing to transfer) are the file's.
  const ChildOutcome xcaf = runInChild(impl, "reading", [](CadModel::Impl& i) { return readStepXcaf(i); });
  if (xcaf.kind == ChildOutcome::Done) {
    if (!xcaf.payload.empty()) impl.readWarnings.push_back(xcaf.payload);
    return;
  }
  if (xcaf.kind == ChildOutcome::Input) throw InputError(xcaf.message);
  // 2: the plain reader, without the XCAF document (no part names).
  const ChildOutcome plain = runInChild(impl, "reading", [](CadModel::Impl& i) { return readStepPlain(i); });
  if (plain.kind == ChildOutcome::Done) {
    impl.readWarnings.push_back("the XCAF STEP reader failed (" + failure(xcaf) +
                                "); read by the plain reader, without part names");
    if (!plain.payload.empty()) impl.readWarnings.push_back(plain.payload);
    return;
  }
  // 3: root by root, skipping the roots that fail.
  const ChildOutcome roots = runInChild(impl, "reading", [](CadModel::Impl& i) { return readStepRoots(i); });
  if (roots.kind == ChildOutcome::Done) {
    impl.readWarnings.push_back("the XCAF and plain STEP readers failed (" + failure(xcaf) + "; " + failure(plain) +
                                "); read root by root, without part names" +
                                (roots.payload.empty() ? std::string() : "; " + roots.payload));
    return;
  }
  const bool crashed = xcaf.kind == ChildOutcome::Crashed || plain.kind == ChildOutcome::Crashed ||
                       roots.kind == ChildOutcome::Crashed;
  throw InputError(impl.path + ": OpenCASCADE could not read this STEP file (" +
                   (crashed ? std::string("it crashed in the reader") : failure(roots)) +
                   "); tried the XCAF, plain and per-part readers");
}

}  // namespace aniso::cad::detail
