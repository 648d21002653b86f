#include "framework/plot/test/fake_surface.h"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "framework/core/config_node.h"
#include "framework/core/quantity.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"
#include "framework/plot/test/fake_laws.h"

namespace fitfeel::plot::testing {
namespace {

class LengthGeometry final : public Geometry {
 public:
  LengthGeometry(double diameter, double length) : diameter_(diameter), length_(length) {}

 protected:
  double DoNominalArea() const override { return std::numbers::pi * diameter_ * length_; }
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override { return "test cylinder"; }

 private:
  double diameter_, length_;
};

class GridDiscretizer final : public Discretizer {
 protected:
  SurfaceGrid DoDiscretize(const PartSpec& part, const Resolution& resolution) const override {
    SurfaceGrid g;
    g.rows = resolution.is_auto() ? 20 : resolution.rows;
    g.columns = resolution.is_auto() ? 36 : resolution.columns;
    const double length = part.geometry->mating_length();
    g.row_position =
        Eigen::VectorXd::LinSpaced(g.rows, 0.5 * length / g.rows, length - 0.5 * length / g.rows);
    g.column_angle.resize(g.columns);
    for (int j = 0; j < g.columns; ++j)
      g.column_angle(j) = (j + 0.5) * 2 * std::numbers::pi / g.columns;
    g.centre.setZero(3, g.size());
    g.normal.setZero(3, g.size());
    g.area.setConstant(g.size(), part.geometry->nominal_area() / g.size());
    return g;
  }
};

class UniformGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec& part, const SurfaceGrid& grid, TextureMode,
                            Rng& rng) const override {
    SkinModelShape sms;
    sms.grid = grid;
    std::uniform_real_distribution<double> draw(0.5 * part.size.lower_deviation,
                                                0.5 * part.size.upper_deviation);
    sms.variation.resize(grid.size());
    for (int k = 0; k < grid.size(); ++k) sms.variation(k) = draw(rng);
    sms.dimension_part = sms.variation;
    sms.form_part.setZero(grid.size());
    sms.surface_part.setZero(grid.size());
    return sms;
  }
};

class FacingAnalyzer final : public ContactAnalyzer {
 protected:
  void DoPrepare(const PartSpec&, const SkinModelShape& inner_sms, const PartSpec&,
                 const SkinModelShape& outer_sms, const ModelSettings&) override {
    inner_ = inner_sms.variation;
    outer_min_ = outer_sms.variation.minCoeff();
  }
  void DoEvaluate(const MatingPose&, ContactState*) const noexcept override {}
  void DoInterferenceMap(const MatingPose&, Eigen::VectorXd* delta) const override {
    *delta = (inner_.array() - outer_min_).max(0.0).matrix();
  }

 private:
  Eigen::VectorXd inner_;
  double outer_min_ = 0.0;
};

class TestCylinder final : public SurfaceType {
 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override {
    return {FormCharacteristic::kRoundness};
  }
  std::vector<std::string> DoLawNames() const override { return {"lame", "ideal"}; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override {
    return std::make_unique<GridDiscretizer>();
  }
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override {
    return std::make_unique<UniformGenerator>();
  }
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override {
    return std::make_unique<FacingAnalyzer>();
  }

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec& part,
                                                  const ConfigNode& node) const override {
    node.ExpectOnlyKeys({"length"});
    const double length = node.Child("length").AsQuantityIn(
        Dimension::kLength, 0.0, std::numeric_limits<double>::infinity(), false);
    return std::make_shared<LengthGeometry>(part.size.nominal, length);
  }
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view name) const override {
    if (name == "lame") return std::make_unique<LameLaw>();
    return std::make_unique<NoPressureLaw>();
  }
};

class StillDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override { return DeviceSpec{}; }

 protected:
  void DoConfigure(const ConfigNode& node) override { node.ExpectOnlyKeys({"plugin"}); }
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override { out->time = time; }
  void DoWrite(const Wrench&) noexcept override {}
};

template <typename Base, typename T>
void* Make() {
  return static_cast<void*>(static_cast<Base*>(new T));
}

}  // namespace

void RegisterPlotFakes(PluginRegistry& registry) {
  registry.AddEntry({"test.plot.cylinder", kFitfeelSurfacePlugin, "1.0.0", "plot test cylinder",
                     &Make<SurfaceType, TestCylinder>});
  registry.AddEntry({"test.plot.device", kFitfeelDevicePlugin, "1.0.0", "plot test device",
                     &Make<Device, StillDevice>});
}

}  // namespace fitfeel::plot::testing
