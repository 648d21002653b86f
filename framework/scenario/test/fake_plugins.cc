#include "framework/scenario/test/fake_plugins.h"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

#include "framework/core/config_node.h"
#include "framework/core/quantity.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"

namespace fitfeel::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

class FakeGeometry final : public Geometry {
 public:
  FakeGeometry(double diameter, double length) : diameter_(diameter), length_(length) {}

 protected:
  double DoNominalArea() const override { return std::numbers::pi * diameter_ * length_; }
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override {
    return "cylinder d=" + FormatQuantity(diameter_, Dimension::kLength) +
           " l=" + FormatQuantity(length_, Dimension::kLength);
  }

 private:
  double diameter_;
  double length_;
};

class FakeCylinder : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override {
    return {FormCharacteristic::kAxisStraightness, FormCharacteristic::kGeneratrixStraightness,
            FormCharacteristic::kRoundness, FormCharacteristic::kCylindricity};
  }
  std::vector<std::string> DoLawNames() const override { return {"gps", "ve1"}; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override { return nullptr; }
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override { return nullptr; }
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override { return nullptr; }

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& node) const override {
    if (part.role == Role::kOuter) {
      node.ExpectOnlyKeys({"length", "outer_diameter"});
    } else {
      node.ExpectOnlyKeys({"length"});
    }
    const double length =
        node.Child("length").AsQuantityIn(Dimension::kLength, 0.0, kInfinity, false);
    if (part.role == Role::kOuter) {
      node.Child("outer_diameter")
          .AsQuantityIn(Dimension::kLength, part.size.nominal, kInfinity, false);
    }
    return std::make_shared<FakeGeometry>(part.size.nominal, length);
  }
  void DoCheckPair(const PartSpec& inner, const PartSpec& outer,
                   const ConfigNode& pair_node) const override {
    if (inner.size.nominal != outer.size.nominal) {
      pair_node.Fail("parts of the same nominal size",
                     FormatQuantity(inner.size.nominal, Dimension::kLength) + " and " +
                         FormatQuantity(outer.size.nominal, Dimension::kLength));
    }
  }
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view) const override { return nullptr; }
  std::shared_ptr<const SurfaceOptions> DoParseOptions(const ConfigNode& options) const override {
    options.ExpectOnlyKeys({"tabulate"});
    auto parsed = std::make_shared<FakeOptions>();
    if (auto tabulate = options.Find("tabulate")) parsed->tabulate = tabulate->AsBool();
    return parsed;
  }
};

class FakeThread final : public FakeCylinder {
 protected:
  bool DoRendersForces() const override { return false; }
  std::vector<std::string> DoLawNames() const override { return {}; }
  std::string DoLimitation() const override { return "thread resistance laws are not written yet"; }
};

class FakeDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override { return DeviceSpec{}; }

 protected:
  void DoConfigure(const ConfigNode& node) override {
    node.ExpectOnlyKeys({"plugin", "speed", "radial_load"});
    speed_ = node.Child("speed").AsQuantityIn(Dimension::kVelocity, 0.0, kInfinity, false);
    radial_load_ = node.Child("radial_load").AsQuantityIn(Dimension::kForce, 0.0, kInfinity);
  }
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    out->position.y() = speed_ * time;
  }
  void DoWrite(const Wrench&) noexcept override {}

 private:
  double speed_ = 0.0;
  double radial_load_ = 0.0;
};

template <typename Base, typename T>
void* Make() {
  return static_cast<void*>(static_cast<Base*>(new T));
}

}  // namespace

void RegisterFakePlugins(PluginRegistry& registry) {
  registry.AddEntry({"test.surface.cylinder", kFitfeelSurfacePlugin, "1.0.0", "fake cylinder",
                     &Make<SurfaceType, FakeCylinder>});
  registry.AddEntry({"test.surface.thread", kFitfeelSurfacePlugin, "1.0.0", "fake thread",
                     &Make<SurfaceType, FakeThread>});
  registry.AddEntry({"test.device.fake", kFitfeelDevicePlugin, "1.0.0", "fake device",
                     &Make<Device, FakeDevice>});
}

}  // namespace fitfeel::test
