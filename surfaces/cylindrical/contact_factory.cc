#include "surfaces/cylindrical/contact_factory.h"

#include "surfaces/cylindrical/cylinder_contact_analyzer.h"
#include "surfaces/cylindrical/cylinder_laws.h"

namespace fitfeel::cylindrical {

std::unique_ptr<ContactAnalyzer> MakeContactAnalyzer() {
  return std::make_unique<CylinderContactAnalyzer>();
}

std::vector<std::string> LawNames() { return {"gps", "elastic", "ve1"}; }

std::unique_ptr<ResistanceLaw> MakeLaw(std::string_view name) {
  if (name == "gps") return std::make_unique<GpsLaw>();
  if (name == "elastic") return std::make_unique<ElasticLaw>();
  if (name == "ve1") return std::make_unique<Ve1Law>();
  return nullptr;
}

}  // namespace fitfeel::cylindrical
