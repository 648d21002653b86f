#include "surfaces/cylindrical/contact_factory.h"

#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"

namespace fitfeel::cylindrical {

std::unique_ptr<ContactAnalyzer> MakeContactAnalyzer() {
  return std::make_unique<CylinderContactAnalyzer>();
}

std::vector<std::string> LawNames() { return {"gps", "ve1"}; }

std::unique_ptr<ResistanceLaw> MakeLaw(std::string_view name) {
  if (name == "gps") return std::make_unique<GpsLaw>();
  if (name == "ve1") return std::make_unique<Ve1Law>();
  return nullptr;
}

}  // namespace fitfeel::cylindrical
