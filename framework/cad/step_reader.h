#pragma once

// The STEP reader (Open CASCADE's STEPCAFControl_Reader) run in the calling process: only the
// reading child of ReadStep (isolated_read.h) calls it, so that a reader crash ends that child
// and not fitfeel.

#include <filesystem>

#include "framework/cad/cad_document.h"

namespace fitfeel::cad {

// Parts, faces, placements and semantic PMI, unchecked. Throws std::runtime_error with the
// reader's complaint for a file it does not read.
CadDocument ReadStepHere(const std::filesystem::path& file);

}  // namespace fitfeel::cad
