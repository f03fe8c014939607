#include "cad/CadModel.h"

#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <filesystem>
#include <fstream>
#include <system_error>

#include "cad/FormatSniff.h"
#include "cad/TopologyBuilder.h"
#include "cad/detail/CadModelImpl.h"
#include "cad/detail/Prepare.h"
#include "cad/detail/Readers.h"
#include "cad/detail/ShapeSummary.h"
#include "mesher/core/Error.h"
#include "mesher/core/Log.h"

namespace aniso::cad {

const char* formatName(CadFormat f) {
  switch (f) {
    case CadFormat::Step: return "STEP";
    case CadFormat::Iges: return "IGES";
    case CadFormat::Brep: return "BREP";
  }
  return "?";
}

const char* overlapPolicyName(OverlapPolicy p) {
  switch (p) {
    case OverlapPolicy::Merge: return "merge";
    case OverlapPolicy::Keep: return "keep";
    case OverlapPolicy::Error: return "error";
  }
  return "?";
}

std::string CadModel::Impl::solidName(const TopoDS_Shape& solid, int id) const {
  const TopoDS_Shape key = solid.Located(TopLoc_Location());
  if (nameIndex.IsBound(key) && !names[static_cast<size_t>(nameIndex.Find(key))].empty())
    return names[static_cast<size_t>(nameIndex.Find(key))];
  return "SOLID" + std::to_string(id);
}

std::string CadModel::Impl::solidColor(const TopoDS_Shape& solid) const {
  const TopoDS_Shape key = solid.Located(TopLoc_Location());
  if (!nameIndex.IsBound(key)) return {};
  const auto k = static_cast<size_t>(nameIndex.Find(key));
  return k < partColors.size() ? partColors[k] : std::string();
}

const FaceTag* CadModel::Impl::faceTag(const TopoDS_Shape& face) const {
  const TopoDS_Shape key = face.Located(TopLoc_Location());
  return faceTagIndex.IsBound(key) ? &faceTags[static_cast<size_t>(faceTagIndex.Find(key))] : nullptr;
}

CadModel::CadModel(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CadModel::CadModel(CadModel&&) noexcept = default;
CadModel& CadModel::operator=(CadModel&&) noexcept = default;
CadModel::~CadModel() = default;

const std::string& CadModel::path() const { return impl_->path; }
CadFormat CadModel::format() const { return impl_->format; }
const std::string& CadModel::fileUnit() const { return impl_->fileUnit; }
int CadModel::solidsLost() const { return impl_->solidsLost; }

namespace {

/// Checks that path is a readable regular file with content; returns its first bytes.
std::string readHead(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(path + ": no such file");
  if (fs::is_directory(st)) throw InputError(path + ": is a directory, not a CAD file");
  if (!fs::is_regular_file(st)) throw InputError(path + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be opened for reading");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  if (head.empty()) throw InputError(path + ": file is empty");
  return head;
}

}  // namespace

CadModel CadModel::read(const std::string& path, const CancelToken* cancel) {
  detail::silenceOcctMessages();
  const std::string head = readHead(path);
  const std::optional<CadFormat> byExt = formatFromExtension(path);
  if (!byExt)
    throw InputError(path + ": unknown CAD file extension (expected .step .stp .igs .iges .brep .brp)");
  const std::optional<CadFormat> byContent = formatFromContent(head);
  if (!byContent) {
    // Binary data or text of another kind: name what the extension promised.
    const char* article = *byExt == CadFormat::Iges ? "an " : "a ";
    throw InputError(path + ": not " + article + formatName(*byExt) + " file (content not recognised)");
  }
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->format = *byContent;
  impl->cancel = cancel;
  switch (impl->format) {
    case CadFormat::Step: detail::readStep(*impl); break;
    case CadFormat::Iges: detail::readIges(*impl); break;
    case CadFormat::Brep: detail::readBrep(*impl); break;
  }
  impl->cancel = nullptr;
  if (impl->shape.IsNull()) throw InputError(path + ": the file contains no shape");
  detail::dropEmptySolids(*impl);
  for (const std::string& w : impl->readWarnings) logWarning(path + ": " + w);
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(impl->shape, TopAbs_FACE, faces);
  TopExp::MapShapes(impl->shape, TopAbs_EDGE, edges);
  if (faces.IsEmpty() && edges.IsEmpty()) {
    // A file that holds faces the transfer dropped says so, with their number.
    if (impl->facesInFile > 0)
      throw InputError(path + ": the model is empty: none of the file's " + std::to_string(impl->facesInFile) +
                       " face(s) could be read (OpenCASCADE rejected their geometry or topology, or no "
                       "shape of the file uses them)");
    throw InputError(path + ": the model is empty (no faces, no edges)");
  }
  return CadModel(std::move(impl));
}

ShapeSummary CadModel::summary() const { return detail::summarize(*impl_); }

PrepareReport CadModel::prepare(const PrepareOptions& options) {
  PrepareReport report;
  impl_->cancel = options.cancel;
  struct Reset {  // the token lives no longer than this call
    Impl& impl;
    ~Reset() { impl.cancel = nullptr; }
  } reset{*impl_};
  const double diag = detail::exactBoundingBox(impl_->shape).diagonal();
  // each step in a child process: a crash of OCCT costs that step only (detail/Prepare.h)
  if (options.fix)
    detail::runPrepareStep("shape fixing", "prepare-fix", *impl_, report,
                           [&](Impl& impl, PrepareReport& r) { detail::fixShape(impl, diag, r); });
  if (options.sew)
    detail::runPrepareStep("sewing", "prepare-sew", *impl_, report, [&](Impl& impl, PrepareReport& r) {
      detail::sewLooseFaces(impl, options.sewRelTolerance * diag, r);
    });
  if (options.fragment)
    detail::runPrepareStep("fragmenting the solids", "prepare-fragment", *impl_, report,
                           [&](Impl& impl, PrepareReport& r) { detail::fragmentSolids(impl, diag, options.overlaps, r); });
  return report;
}

Model CadModel::topology() const {
  const Impl& impl = *impl_;
  Model model = buildTopology(
      impl.shape, [&impl](const TopoDS_Shape& s, int id) { return impl.solidName(s, id); },
      [&impl](const TopoDS_Shape& s) { return detail::solidVolumeOf(impl, s); });
  if (!impl.faceTagIndex.IsEmpty()) {  // face ids: MapShapes order, as buildTopology's
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(impl.shape, TopAbs_FACE, faces);
    for (int i = 1; i <= faces.Extent() && i <= static_cast<int>(model.faces.size()); ++i)
      if (const FaceTag* tag = impl.faceTag(faces(i))) model.faces[static_cast<size_t>(i - 1)].name = tag->name;
  }
  return model;
}

void CadModel::writeBrep(const std::string& path) const {
  try {
    if (!BRepTools::Write(impl_->shape, path.c_str()))
      throw InputError(path + ": cannot write BREP file");
  } catch (const Standard_Failure& e) {
    throw InputError(path + ": OpenCASCADE failed writing BREP: " + e.GetMessageString());
  }
}

}  // namespace aniso::cad
