// libFuzzer target: the text parsers of user numbers, quantities and ISO 286 codes. Any input
// either parses to a finite value in range or is refused (UserError, or std::invalid_argument from
// ParseQuantity); anything else (a crash,
// another exception, a sanitizer report, a non-finite result) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "framework/core/error.h"
#include "framework/core/quantity.h"
#include "framework/iso286/fit.h"
#include "framework/iso286/iso286.h"

namespace {

constexpr fitfeel::Dimension kDimensions[] = {
    fitfeel::Dimension::kDimensionless, fitfeel::Dimension::kLength,
    fitfeel::Dimension::kForce,         fitfeel::Dimension::kTime,
    fitfeel::Dimension::kFrequency,     fitfeel::Dimension::kVelocity,
    fitfeel::Dimension::kStiffness,     fitfeel::Dimension::kPressure,
    fitfeel::Dimension::kAngle,         fitfeel::Dimension::kMass,
    fitfeel::Dimension::kDamping,       fitfeel::Dimension::kAngularVelocity,
    fitfeel::Dimension::kTorque,        fitfeel::Dimension::kAngularStiffness,
    fitfeel::Dimension::kEnergy,
};

template <typename F>
void Refusable(F&& f) {
  try {
    f();
  } catch (const fitfeel::UserError&) {
    // A refusal with its reason: what the parsers promise for bad text.
  } catch (const std::invalid_argument&) {
    // ParseQuantity's refusal (ConfigNode turns it into a located ScenarioError).
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // The first byte picks the dimension; the rest is the text.
  const fitfeel::Dimension dimension =
      kDimensions[data[0] % (sizeof(kDimensions) / sizeof(kDimensions[0]))];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  Refusable([&] {
    const double v = fitfeel::ParseQuantity(text, dimension);
    if (!std::isfinite(v)) std::abort();
  });
  // nullopt: refused; a value: inside the range asked for.
  const std::optional<long> n = fitfeel::ParseInteger(text, 0, 1000000);
  if (n && (*n < 0 || *n > 1000000)) std::abort();
  // ISO 286: "<code>" at 20 mm and "<hole>/<shaft>" fits, as `fitfeel fit 20 <text>` reads them.
  Refusable([&] { (void)fitfeel::iso286::Lookup(0.02, text); });
  Refusable([&] { (void)fitfeel::iso286::LookupFit(0.02, text); });
  return 0;
}
