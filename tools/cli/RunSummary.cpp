#include "tools/cli/RunSummary.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "mesher/core/FileExtension.h"
#include "mesher/core/Log.h"
#include "tools/app/InfoJson.h"

namespace aniso::cli {
namespace {

using json = nlohmann::ordered_json;

/// Width of the longest histogram bar, characters.
constexpr int kHistogramBarWidth = 40;

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

/// "12 tetrahedra", "1 part": a count with its noun, plural by count.
std::string counted(long long n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

double number(const json& j, const char* key, double otherwise = 0) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : otherwise;
}

/// The unit lengths are in: OpenCASCADE converts STEP and IGES to millimetres (from the
/// file's unit, the model's "file_unit"); BREP and analytic models carry no unit.
std::string unitsText(const std::string& input, const json& model) {
  const std::string ext = lowerExtension(input);
  if (ext == ".step" || ext == ".stp" || ext == ".igs" || ext == ".iges") {
    const std::string unit = model.is_object() ? model.value("file_unit", std::string()) : std::string();
    return "lengths in " + app::unitsPhrase(cad::CadFormat::Step, unit);
  }
  return "lengths in the file's units";
}

std::string sizeText(const std::string& path) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) return "size unknown";
  const double b = static_cast<double>(bytes);
  if (b >= 1e9) return format("%.2f GB", b / 1e9);
  if (b >= 1e6) return format("%.1f MB", b / 1e6);
  if (b >= 1e3) return format("%.1f kB", b / 1e3);
  return std::to_string(bytes) + " bytes";
}

void addPartsLine(const io::Report& r, std::vector<std::string>& out) {
  const json& model = r.extra.contains("model") ? r.extra["model"] : json::object();
  std::string line = r.input + " (" + unitsText(r.input, model) + ")";
  if (model.contains("solid_list")) {
    const json& list = model["solid_list"];
    line += ": " + counted(static_cast<long long>(list.size()), "part", "parts");
    if (!list.empty() && list.size() <= 3) {
      std::string names;
      for (const json& s : list) names += (names.empty() ? "" : ", ") + s.value("name", std::string());
      line += " (" + names + ")";
    }
  }
  if (model.contains("faces")) line += ", " + counted(model["faces"].get<long long>(), "face", "faces");
  out.push_back(line);
}

void addElementsLine(const io::Report& r, std::vector<std::string>& out) {
  std::vector<std::string> parts;
  const bool quadratic = number(r.options, "order", 1) == 2;
  if (r.tetrahedra) parts.push_back(counted(r.tetrahedra, "tetrahedron", "tetrahedra") + (quadratic ? " (10-node)" : ""));
  const std::string surface = r.tetrahedra ? "boundary " : "";
  if (r.triangles) parts.push_back(counted(r.triangles, surface + "triangle", surface + "triangles"));
  if (r.quads) parts.push_back(counted(r.quads, "quad", "quads"));
  parts.push_back(counted(r.nodes, "node", "nodes"));
  std::string line;
  for (const std::string& p : parts) line += (line.empty() ? "" : ", ") + p;
  out.push_back(line);
}

/// "0.8-0.9  1234  ########", the bins from the first to the last non-empty one.
void addHistogram(const json& h, std::vector<std::string>& out) {
  if (!h.contains("bins")) return;
  const std::vector<long long> bins = h["bins"].get<std::vector<long long>>();
  const double lo = number(h, "lo"), hi = number(h, "hi", 1);
  const auto first = std::find_if(bins.begin(), bins.end(), [](long long n) { return n > 0; });
  if (first == bins.end()) return;
  const auto last = std::find_if(bins.rbegin(), bins.rend(), [](long long n) { return n > 0; }).base();
  const long long most = *std::max_element(bins.begin(), bins.end());
  const double width = (hi - lo) / static_cast<double>(bins.size());
  for (auto it = first; it != last; ++it) {
    const double a = lo + width * static_cast<double>(it - bins.begin());
    const int bar = static_cast<int>((kHistogramBarWidth * *it + most - 1) / most);
    out.push_back(format("  %.1f-%.1f %9.0f ", a, a + width, static_cast<double>(*it)) + std::string(static_cast<std::size_t>(bar), '#'));
  }
}

void addQuality(const io::Report& r, std::vector<std::string>& out) {
  if (!r.quality.contains("elements")) return;
  const json& q = r.quality["elements"];
  if (number(q, "count") > 0) {
    std::string line = "quality of the " + q.value("type", std::string()) +
                       format(" (mean ratio, 1 = regular): min %.3f, mean %.3f", number(q, "min"), number(q, "mean"));
    if (q.contains("dihedral_min")) line += format("; smallest dihedral angle %.1f deg", number(q, "dihedral_min"));
    if (q.contains("angle_min")) line += format("; smallest angle %.1f deg", number(q, "angle_min"));
    out.push_back(line);
    addHistogram(q["histogram"], out);
  }
  if (q.contains("quads")) {
    const json& quads = q["quads"];
    out.push_back(format("quality of the quads (scaled Jacobian, 1 = rectangle): min %.3f, mean %.3f",
                         number(quads, "min"), number(quads, "mean")));
    addHistogram(quads["histogram"], out);
  }
}

void addOverlapWarnings(const io::Report& r, std::vector<std::string>& out) {
  if (!r.extra.contains("model") || !r.extra["model"].contains("overlaps")) return;
  for (const json& o : r.extra["model"]["overlaps"]) {
    const auto name = [&](const char* id, const char* key) {
      return "part " + std::to_string(o.value(id, 0)) + " '" + o.value(key, std::string()) + "'";
    };
    std::string line = "overlapping parts: " + name("a", "name_a") + " and " + name("b", "name_b") +
                       format(" share a volume of %g", number(o, "volume"));
    if (o.contains("assigned_to") && o["assigned_to"].is_number()) {
      const bool a = o["assigned_to"].get<int>() == o.value("a", 0);
      line += "; merged: the common region is meshed once, in " + (a ? name("a", "name_a") : name("b", "name_b"));
    } else
      line += "; kept as they are: the meshes overlap and are not connected";
    out.push_back(line);
  }
}

/// Faces the thin-wall warning lists by id.
constexpr int kSummaryMaxFaces = 8;

void addSizingWarnings(const io::Report& r, std::vector<std::string>& out) {
  const json& px = r.extra.contains("proximity") ? r.extra["proximity"] : json::object();
  if (number(px, "rounds") > 0) {
    // the faces refined (1-based, at most kSummaryMaxFaces) and the smallest size asked
    std::string faces;
    double smallest = 0;
    int listed = 0, total = 0;
    if (px.contains("refined"))
      for (const json& e : px["refined"]) {
        ++total;
        const double h = number(e, "size");
        if (smallest == 0 || h < smallest) smallest = h;
        if (listed < kSummaryMaxFaces) faces += (listed++ ? ", " : "") + std::to_string(e.value("face", 0));
      }
    if (total > listed) faces += format(" and %.0f more", static_cast<double>(total - listed));
    if (total == 0)  // only the sources of solids the volume mesher failed on
      out.push_back(format("the surface was meshed again %.0f time(s), finer on the solids the volume mesher could "
                           "not mesh at first",
                           number(px, "rounds")));
    else
      out.push_back(format("thin walls: the surface was meshed again %.0f time(s), finer where a part is thinner "
                         "than its elements (element size down to %g on face(s) ",
                         number(px, "rounds"), smallest) +
                  faces + "); the element count grew accordingly");
  }
  const json& cr = r.extra.contains("cracks") ? r.extra["cracks"] : json::object();
  if (number(cr, "faces") > 0) {
    std::string ids;
    for (const json& f : cr["face_ids"]) ids += (ids.empty() ? "" : ", ") + std::to_string(f.get<int>());
    out.push_back("crack: face(s) " + ids +
                  format(" inside a solid meshed two-sided (%.0f nodes doubled so the sides separate); "
                         "--internal-faces bond keeps them joined",
                         number(cr, "nodes_duplicated")));
  }
  const json& cs = r.extra.contains("coarse_solids") ? r.extra["coarse_solids"] : json::object();
  if (cs.value("refined_kept", false))
    out.push_back(format("%.0f solid(s) below the quality bar were meshed again with a finer surface",
                         number(cs, "solids")));
  const json& b = r.extra.contains("budget") ? r.extra["budget"] : json::object();
  if (b.contains("coarsened_faces") && !b["coarsened_faces"].empty())
    out.push_back(format("element budget: sizes below %g raised to it on %.0f face(s) (--max-elements %.0f)",
                         number(b, "floor"), static_cast<double>(b["coarsened_faces"].size()), number(b, "limit")));
}

void addProblemWarnings(const io::Report& r, std::vector<std::string>& out) {
  int shown = 0, more = 0;
  for (const Problem& p : r.problems) {
    if (p.severity == Severity::Note) continue;
    if (shown == kSummaryMaxProblems) {
      ++more;
      continue;
    }
    ++shown;
    out.push_back(entityLabel(p.entity) + (p.severity == Severity::Failed ? " left out: " : " degraded: ") + p.detail);
  }
  if (more) out.push_back("and " + std::to_string(more) + " more problems (see --report FILE.json)");
}

}  // namespace

RunSummaryText runSummary(const io::Report& r, const std::string& output) {
  RunSummaryText s;
  addPartsLine(r, s.lines);
  addElementsLine(r, s.lines);
  addQuality(r, s.lines);
  s.lines.push_back("wrote " + output + " (" + sizeText(output) + ") in " + format("%.2f s", r.totalSeconds));
  addOverlapWarnings(r, s.warnings);
  addSizingWarnings(r, s.warnings);
  addProblemWarnings(r, s.warnings);
  return s;
}

void printRunSummary(const io::Report& report, const std::string& output) {
  const RunSummaryText s = runSummary(report, output);
  for (const std::string& line : s.lines) logNotice(line);
  for (const std::string& w : s.warnings) logWarning(w);
}

}  // namespace aniso::cli
