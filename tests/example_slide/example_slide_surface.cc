#include "tests/example_slide/example_slide_surface.h"

#include <cmath>

#include "tests/example_slide/example_slide_contact_analyzer.h"
#include "tests/example_slide/example_slide_geometry.h"
#include "tests/example_slide/example_slide_law.h"
#include "tests/example_slide/example_slide_shape.h"

namespace fitfeel::example_slide {

std::unique_ptr<Discretizer> SlideSurface::DoMakeDiscretizer() const {
  return std::make_unique<SlideDiscretizer>();
}

std::unique_ptr<VariationGenerator> SlideSurface::DoMakeVariationGenerator() const {
  return std::make_unique<SlideVariationGenerator>();
}

std::unique_ptr<ContactAnalyzer> SlideSurface::DoMakeContactAnalyzer() const {
  return std::make_unique<SlideContactAnalyzer>();
}

std::shared_ptr<const Geometry> SlideSurface::DoParseGeometry(const PartSpec& part,
                                                              const ConfigNode& geometry) const {
  return ParseSlideGeometry(part, geometry);
}

void SlideSurface::DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                               const ConfigNode& pair_node) const {
  const SlideGeometry& a = SlideGeometryOf(inner);
  const SlideGeometry& b = SlideGeometryOf(outer);
  // Both variations are deviations from one nominal width (eq. 8 subtracts them), and the cells
  // face each other only if both flanks have the same height.
  if (std::abs(a.width() - b.width()) > 1e-12 || std::abs(a.height() - b.height()) > 1e-12) {
    pair_node.Fail(
        "the same nominal size and flank height on '" + inner.name + "' and '" + outer.name + "'",
        a.Describe() + " and " + b.Describe());
  }
}

std::unique_ptr<ResistanceLaw> SlideSurface::DoMakeLaw(std::string_view name) const {
  if (name == "spring") return std::make_unique<SlideSpringLaw>();
  return nullptr;
}

std::vector<CharacteristicCheck> SlideSurface::DoEvaluateCharacteristics(
    const PartSpec& part, const SkinModelShape& sms) const {
  return EvaluateSlideCharacteristics(part, sms);
}

}  // namespace fitfeel::example_slide
