#pragma once

#include <limits>

// A small, fully controlled surface type and device for the run-time tests: the surface draws its
// skin model shapes from the scene's generator (so the seed changes the forces), the device moves
// the part at constant speed along the mating axis.

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"
#include "framework/scenario/scene.h"

namespace fitfeel::testing {

class FakeGeometry final : public Geometry {
 protected:
  double DoNominalArea() const override { return 1e-3; }
  double DoMatingLength() const override { return 0.02; }
  std::string DoDescribe() const override { return "fake"; }
};

class FakeDiscretizer final : public Discretizer {
 protected:
  SurfaceGrid DoDiscretize(const PartSpec&, const Resolution& r) const override {
    SurfaceGrid g;
    g.rows = r.rows > 0 ? r.rows : 4;
    g.columns = r.columns > 0 ? r.columns : 8;
    g.row_position = Eigen::VectorXd::LinSpaced(g.rows, 0.0, 0.02);
    g.column_angle =
        Eigen::VectorXd::LinSpaced(g.columns, 0.0, 2 * M_PI * (g.columns - 1) / g.columns);
    g.centre = Eigen::Matrix3Xd::Zero(3, g.size());
    g.normal = Eigen::Matrix3Xd::Zero(3, g.size());
    g.area = Eigen::VectorXd::Constant(g.size(), 1e-3 / g.size());
    return g;
  }
};

// V uniform in +-5 um per cell.
class FakeGenerator final : public VariationGenerator {
 protected:
  SkinModelShape DoGenerate(const PartSpec&, const SurfaceGrid& grid, TextureMode,
                            Rng& rng) const override {
    SkinModelShape s;
    s.grid = grid;
    std::uniform_real_distribution<double> u(-5e-6, 5e-6);
    s.variation.resize(grid.size());
    for (int i = 0; i < grid.size(); ++i) s.variation[i] = u(rng);
    s.dimension_part = s.variation;
    s.form_part = Eigen::VectorXd::Zero(grid.size());
    s.surface_part = Eigen::VectorXd::Zero(grid.size());
    return s;
  }
};

// Clearance = 10 um + mean(V_outer) - mean(V_inner); radial penetration beyond it.
class FakeAnalyzer final : public ContactAnalyzer {
 public:
  double clearance() const { return clearance_; }

 protected:
  void DoPrepare(const PartSpec&, const SkinModelShape& inner, const PartSpec&,
                 const SkinModelShape& outer, const ModelSettings&) override {
    clearance_ = 10e-6 + outer.variation.mean() - inner.variation.mean();
  }
  void DoEvaluate(const MatingPose& pose, ContactState* out) const noexcept override {
    out->engaged = pose.depth > 0.0;
    out->engaged_length = std::max(0.0, pose.depth);
    out->offset_distance = pose.offset.norm();
    out->offset_angle = std::atan2(pose.offset.y(), pose.offset.x());
    out->assembly_extent = clearance_;
    out->penetration = out->engaged ? std::max(0.0, out->offset_distance - clearance_) : 0.0;
  }

 private:
  double clearance_ = 0.0;
};

// Eq. 9 on the fake contact state, plus a NaN when asked (to exercise the guard).
class FakeLaw final : public ResistanceLaw {
 public:
  explicit FakeLaw(bool nan_beyond = false) : nan_(nan_beyond) {}

 protected:
  void DoPrepare(const PartSpec&, const PartSpec&, const ModelSettings& s) override {
    k_ = s.contact_stiffness;
    mu_ = s.friction;
  }
  void DoEvaluate(const ContactState& c, const MatingMotion&, Wrench* out) const noexcept override {
    const double f = k_ * c.penetration;
    out->force.x() = -f * std::cos(c.offset_angle);
    out->force.z() = -f * std::sin(c.offset_angle);
    // Even with no radial penetration, a press-fit-like axial term from the engaged length keeps
    // the seed visible in fy: it scales with the drawn clearance.
    out->force.y() =
        c.engaged ? -mu_ * f - 1e5 * c.engaged_length * std::abs(c.assembly_extent) : 0.0;
    if (nan_ && c.engaged_length > 0.005) out->force.y() = std::nan("");
  }

 private:
  double k_ = 0.0, mu_ = 0.0;
  bool nan_;
};

class FakeSurface final : public SurfaceType {
 public:
  explicit FakeSurface(bool nan_law = false, bool fail_prepare = false)
      : nan_law_(nan_law), fail_prepare_(fail_prepare) {}

 protected:
  std::vector<FormCharacteristic> DoFormCharacteristics() const override { return {}; }
  std::vector<std::string> DoLawNames() const override { return {"fake"}; }
  std::unique_ptr<Discretizer> DoMakeDiscretizer() const override {
    return std::make_unique<FakeDiscretizer>();
  }
  std::unique_ptr<VariationGenerator> DoMakeVariationGenerator() const override {
    if (fail_prepare_) throw UserError("fake surface refuses to prepare");
    return std::make_unique<FakeGenerator>();
  }
  std::unique_ptr<ContactAnalyzer> DoMakeContactAnalyzer() const override {
    return std::make_unique<FakeAnalyzer>();
  }

  std::shared_ptr<const Geometry> DoParseGeometry(const PartSpec&,
                                                  const ConfigNode&) const override {
    return std::make_shared<FakeGeometry>();
  }
  std::unique_ptr<ResistanceLaw> DoMakeLaw(std::string_view) const override {
    return std::make_unique<FakeLaw>(nan_law_);
  }

 private:
  bool nan_law_;
  bool fail_prepare_;
};

// A device without a motor, as the simulated robot: unlimited force and stiffness, no damping.
inline DeviceSpec UnlimitedSpec() {
  DeviceSpec spec;
  spec.model = "fake unlimited device";
  spec.max_force = std::numeric_limits<double>::infinity();
  spec.max_continuous_force = spec.max_force;
  spec.max_stiffness = spec.max_force;
  spec.workspace = Eigen::Vector3d::Constant(1.0);
  return spec;
}

// Moves the leading end at constant speed along +y from `start` with a fixed radial offset, and
// remembers what it was asked to render.
class KinematicDevice final : public Device {
 public:
  KinematicDevice(double start_y, double speed, Eigen::Vector2d offset = {0.0, 0.0})
      : start_y_(start_y), speed_(speed), offset_(offset) {}
  DeviceSpec DoSpec() const override { return spec_; }
  void set_spec(const DeviceSpec& spec) { spec_ = spec; }
  int writes() const { return writes_; }
  const Wrench& last() const { return last_; }
  bool started() const { return started_; }
  bool stopped() const { return stopped_; }
  double stiffness() const { return stiffness_; }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override { started_ = true; }
  void DoStop() noexcept override { stopped_ = true; }
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    out->position = Eigen::Vector3d(offset_.x(), start_y_ + speed_ * time, offset_.y());
    out->velocity = Eigen::Vector3d(0.0, speed_, 0.0);
  }
  void DoSetEnvironmentStiffness(double k) noexcept override { stiffness_ = k; }
  void DoWrite(const Wrench& w) noexcept override {
    last_ = w;
    ++writes_;
  }

 private:
  double start_y_, speed_;
  Eigen::Vector2d offset_;
  DeviceSpec spec_ = UnlimitedSpec();
  Wrench last_;
  int writes_ = 0;
  bool started_ = false, stopped_ = false;
  double stiffness_ = -1.0;
};

inline Scene MakeFakeScene(std::uint64_t seed, double duration = 1.0,
                           std::shared_ptr<Device> device = nullptr,
                           std::shared_ptr<const SurfaceType> surface = nullptr) {
  Scene scene;
  scene.file = "fake.yaml";
  scene.name = "fake";
  scene.surface_id = "fitfeel.surface.fake";
  scene.surface = surface ? surface : std::make_shared<FakeSurface>();
  scene.inner.name = "shaft";
  scene.inner.role = Role::kInner;
  scene.inner.geometry = std::make_shared<FakeGeometry>();
  scene.outer.name = "bushing";
  scene.outer.role = Role::kOuter;
  scene.outer.geometry = std::make_shared<FakeGeometry>();
  scene.model.law = "fake";
  scene.model.friction = 0.15;
  scene.model.contact_stiffness = 1e5;
  scene.device_id = "fitfeel.device.kinematic";
  // Offset 20 um: inside the capture radius, beyond the +-10 um fake clearance for most seeds.
  scene.device =
      device ? device
             : std::make_shared<KinematicDevice>(-1e-3, 10e-3, Eigen::Vector2d(0.0, -20e-6));
  scene.run.rate = 1000.0;
  scene.run.duration = duration;
  scene.run.seed = seed;
  scene.run.clock = ClockMode::kVirtual;
  return scene;
}

}  // namespace fitfeel::testing
