#pragma once
// Internal: the three readers. Each fills impl.shape (and impl's part names for STEP) or
// throws InputError naming the file; none lets an OCCT exception escape.
#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

void readStep(CadModel::Impl& impl);
void readIges(CadModel::Impl& impl);
void readBrep(CadModel::Impl& impl);

/// Removes OCCT's default console printers once, so that library code prints nothing.
void silenceOcctMessages();

}  // namespace aniso::cad::detail
