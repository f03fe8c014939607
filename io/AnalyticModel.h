#pragma once
// Analytic models: a surface patch described in JSON, meshed like a CAD face (docs/import.md,
// "Analytic models"). Used for the thesis examples (appendix A: RECT1, AN1, SURF0-2).
//
//   {"name": "AN1",
//    "surface": {"type": "plane"} | {"type": "plane", "origin": [x,y,z], "u_axis": [...], "v_axis": [...]}
//             | {"type": "expression", "x": "u", "y": "v", "z": "0.5*sin(u)"},
//    "domain": {"u": [u0, u1], "v": [v0, v1]},
//    "holes": [{"type": "circle", "center": [u, v], "radius": r},
//              {"type": "polygon", "points": [[u, v], ...]}],
//    "sizing": {"angle": "pi/6", "h1": "0.01", "h2": "0.0101 - 0.005*u"}}
//
// The result is a Model of one face whose outer loop is the domain rectangle
// (counter-clockwise, four line edges) and whose holes are inner loops (clockwise), each
// edge's 3D curve being the surface composed with its pcurve. Holes must lie strictly
// inside the domain and be disjoint: this is checked.
#include <optional>
#include <string>

#include "mesher/model/Model.h"

namespace aniso::io {

/// The user's analytic sizing (thesis eq. 2.4 / A.1): expressions in u, v of the angle of
/// the first direction and the two lengths, in the parametric plane.
struct AnalyticSizing {
  std::string angle = "0", h1, h2;
};

struct AnalyticModel {
  std::string name;
  Model model;
  std::optional<AnalyticSizing> sizing;
};

/// Is this path an analytic model (by extension .json, any case)?
bool isAnalyticModelPath(const std::string& path);

/// Reads and checks an analytic model. Throws InputError naming the file and the problem
/// (missing file, not JSON, missing or wrong field, bad expression, hole outside the domain
/// or overlapping another).
AnalyticModel readAnalyticModel(const std::string& path);

}  // namespace aniso::io
