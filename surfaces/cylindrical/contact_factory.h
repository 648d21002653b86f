#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"

namespace fitfeel::cylindrical {

// Implemented with the contact analysis (sources_contact.cmake); used by the surface type.
std::unique_ptr<ContactAnalyzer> MakeContactAnalyzer();
// Law names offered, default first: "gps" (paper eqs. 9-12) and "ve1" (ideal geometry baseline).
std::vector<std::string> LawNames();
// Returns null for a name not in LawNames().
std::unique_ptr<ResistanceLaw> MakeLaw(std::string_view name);

}  // namespace fitfeel::cylindrical
