#pragma once

#include <span>
#include <string_view>

namespace fitfeel::thread {

// Strength of a bolt property class, ISO 898-1, in pascals. The yield strength is the lower yield
// strength R_eL for 4.6 and 5.6 and the 0.2 % proof strength R_p0.2 for 8.8, 10.9 and 12.9; VDI
// 2230 calls both R_p0.2 in its elastic-limit check. Class 8.8 has higher minima above d = 16 mm
// (R_m 830 instead of 800 MPa, R_p0.2 660 instead of 640 MPa), hence the diameter argument.
class BoltPropertyClass {
 public:
  // "4.6", "5.6", "8.8", "10.9" or "12.9"; anything else throws UserError listing those.
  static const BoltPropertyClass& Parse(std::string_view name);
  static std::span<const BoltPropertyClass> All();

  std::string_view name() const { return name_; }
  double nominal_tensile_strength() const { return tensile_nominal_; }
  // Minimum tensile strength R_m,min and minimum yield strength for a bolt of nominal diameter d
  // (metres, finite and positive).
  double min_tensile_strength(double nominal_diameter) const;
  double min_yield_strength(double nominal_diameter) const;

  constexpr BoltPropertyClass(std::string_view name, double tensile_nominal, double tensile_min,
                              double yield_min, double tensile_min_large, double yield_min_large)
      : name_(name),
        tensile_nominal_(tensile_nominal),
        tensile_min_(tensile_min),
        yield_min_(yield_min),
        tensile_min_large_(tensile_min_large),
        yield_min_large_(yield_min_large) {}

 private:
  std::string_view name_;
  double tensile_nominal_;
  double tensile_min_, yield_min_;              // d <= 16 mm
  double tensile_min_large_, yield_min_large_;  // d > 16 mm
};

}  // namespace fitfeel::thread
