#pragma once

// The two trivial objects the test plugins make. Header-only and compiled into each test plugin,
// hidden like everything in a plugin except its hook.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/error.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"

namespace fitfeel::test_plugins {

// A surface type that can be listed and instantiated but models nothing: it stands for a surface
// whose resistance law does not exist yet (renders_forces() is false).
class InertSurface final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override { return {}; }
  std::vector<std::string> DoLawNames() const override { return {}; }
  bool DoRendersForces() const override { return false; }
  std::string DoLimitation() const override {
    return "test surface: parses no geometry and has no resistance law";
  }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override { Unsupported(); }
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override { Unsupported(); }
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override { Unsupported(); }

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec&,
                                                  const ConfigNode&) const override {
    Unsupported();
  }
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view) const override { Unsupported(); }

 private:
  [[noreturn]] void Unsupported() const { throw UnsupportedError(limitation()); }
};

// A device that stays at the origin and remembers what it was told: enough for tests that need a
// Device from a real plugin library (loading, lifetime, scheduler plumbing).
class StillDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override {
    DeviceSpec spec;
    spec.model = "fitfeel test still device";
    spec.max_force = 10.0;
    spec.max_continuous_force = 5.0;
    spec.max_stiffness = 1000.0;
    spec.native_rate = 1000.0;
    return spec;
  }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double period) override { period_ = period; }
  void DoRead(double time, DeviceState* out) noexcept override {
    *out = DeviceState{};
    out->time = time;
    out->delivered = last_;
  }
  void DoWrite(const Wrench& wrench) noexcept override { last_ = wrench; }

 private:
  double period_ = 0.0;
  Wrench last_;
};

}  // namespace fitfeel::test_plugins
