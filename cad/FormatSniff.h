#pragma once
// Choosing the reader of a CAD file: by content first, by extension second.
#include <optional>
#include <string>

#include "cad/CadModel.h"

namespace aniso::cad {

/// The format named by a file extension (.step .stp .igs .iges .brep .brp, any case),
/// or nothing for any other extension.
std::optional<CadFormat> formatFromExtension(const std::string& path);

/// The format recognised from the first bytes of a file: STEP Part 21 header
/// ("ISO-10303-21;"), BREP text header ("DBRep_DrawableShape" / "CASCADE Topology"), IGES
/// fixed 80-column records with an 'S' section letter in column 73. Nothing if none fits.
std::optional<CadFormat> formatFromContent(const std::string& head);

}  // namespace aniso::cad
