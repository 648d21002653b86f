// The C interface (fitfeel.h) over the framework: a scene prepared once, then stepped by the host
// with its own device states through the same scheduler, stages and safety chain as `fitfeel
// run`, so the same states give the same wrenches bit for bit.
#include "framework/capi/fitfeel.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/run.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"

namespace {
using fitfeel::DeviceState;
using fitfeel::Wrench;
thread_local std::string thread_error;
}  // namespace

// Named, not anonymous: fitfeel_scene (external linkage) holds one, which a unity build's
// -Wsubobject-linkage refuses for a type private to the file.
namespace fitfeel::capi_detail {

// The host's device: Read hands the scheduler the state the host passed to fitfeel_step, Write
// keeps the wrench for the host. Its spec is the scene's device's, so the safety chain limits
// and scales exactly as in `fitfeel run`.
class HostDevice final : public fitfeel::Device {
 public:
  explicit HostDevice(fitfeel::DeviceSpec spec) : spec_(std::move(spec)) {}
  fitfeel::DeviceSpec DoSpec() const override { return spec_; }
  void Set(const DeviceState& state) noexcept { state_ = state; }
  const Wrench& written() const noexcept { return written_; }

 protected:
  void DoConfigure(const fitfeel::ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double, DeviceState* out) noexcept override { *out = state_; }
  void DoWrite(const Wrench& wrench) noexcept override { written_ = wrench; }

 private:
  fitfeel::DeviceSpec spec_;
  DeviceState state_;
  Wrench written_;
};

}  // namespace fitfeel::capi_detail

struct fitfeel_scene {
  std::unique_ptr<fitfeel::PluginRegistry> registry;
  fitfeel::Scene scene;
  fitfeel::PreparedScene prepared;
  std::unique_ptr<fitfeel::Stage> constrained;
  std::unique_ptr<fitfeel::PositioningStage> positioning;
  std::unique_ptr<fitfeel::capi_detail::HostDevice> device;
  std::unique_ptr<fitfeel::Scheduler> scheduler;
  std::string error;
  bool done = false;
};

namespace {

int Fail(int code, const std::exception& e) {
  thread_error = e.what();
  return code;
}

// What RunScene sets up before its loop, with the host's device in place of the scene's.
std::unique_ptr<fitfeel_scene> Make(std::unique_ptr<fitfeel::PluginRegistry> registry,
                                    fitfeel::Scene scene, std::uint64_t seed) {
  auto s = std::make_unique<fitfeel_scene>();
  s->registry = std::move(registry);
  s->scene = std::move(scene);
  if (seed != 0) s->scene.run.seed = seed;
  s->scene.run.clock = fitfeel::ClockMode::kVirtual;  // the host's loop sets the pace
  s->prepared = fitfeel::Prepare(s->scene);
  // The scene's own device, started only to learn its spec (hardware knows it once started).
  s->scene.device->Start(1.0 / s->scene.run.rate);
  const fitfeel::DeviceSpec spec = s->scene.device->spec();
  s->scene.device->Stop();
  fitfeel::SceneStages stages = fitfeel::MakeSceneStages(s->scene, s->prepared, spec);
  s->positioning = std::move(stages.positioning);
  s->constrained = std::move(stages.constrained);
  s->device = std::make_unique<fitfeel::capi_detail::HostDevice>(spec);
  s->device->Start(1.0 / s->scene.run.rate);
  fitfeel::SchedulerSettings settings = fitfeel::SceneSchedulerSettings(s->scene);
  settings.clock = fitfeel::ClockMode::kVirtual;
  settings.safety = fitfeel::RuntimeSafetySettings(s->scene.safety, spec);
  s->scheduler = std::make_unique<fitfeel::Scheduler>(*s->device, *s->positioning,
                                                      *s->constrained, settings);
  return s;
}

template <class Load>
int Open(Load&& load, std::uint64_t seed, fitfeel_scene** out) {
  if (out == nullptr) {
    thread_error = "fitfeel_open: out is null";
    return FITFEEL_INVALID_ARGUMENT;
  }
  *out = nullptr;
  thread_error.clear();
  try {
    auto registry = std::make_unique<fitfeel::PluginRegistry>();
    registry->LoadAll();
    fitfeel::Scene scene = load(*registry);
    *out = Make(std::move(registry), std::move(scene), seed).release();
    return FITFEEL_OK;
  } catch (const fitfeel::ScenarioError& e) {
    return Fail(FITFEEL_SCENARIO_ERROR, e);
  } catch (const std::exception& e) {
    return Fail(FITFEEL_ERROR, e);
  }
}

}  // namespace

extern "C" {

int fitfeel_abi_version(void) { return FITFEEL_C_ABI_VERSION; }

int fitfeel_open_file(const char* path, uint64_t seed, fitfeel_scene** out) {
  if (path == nullptr) {
    thread_error = "fitfeel_open_file: path is null";
    return FITFEEL_INVALID_ARGUMENT;
  }
  return Open([&](const fitfeel::PluginRegistry& r) { return fitfeel::LoadScene(path, r); }, seed,
              out);
}

int fitfeel_open_yaml(const char* yaml, const char* name, uint64_t seed, fitfeel_scene** out) {
  if (yaml == nullptr) {
    thread_error = "fitfeel_open_yaml: yaml is null";
    return FITFEEL_INVALID_ARGUMENT;
  }
  const std::string file = name != nullptr ? name : "<yaml>";
  return Open(
      [&](const fitfeel::PluginRegistry& r) { return fitfeel::LoadSceneFromYaml(yaml, file, r); },
      seed, out);
}

int fitfeel_step(fitfeel_scene* s, const fitfeel_device_state* d, fitfeel_wrench* out) {
  if (s == nullptr || d == nullptr || out == nullptr) return FITFEEL_INVALID_ARGUMENT;
  DeviceState state;
  state.time = d->time;
  state.position = Eigen::Vector3d(d->position[0], d->position[1], d->position[2]);
  state.orientation =
      Eigen::Quaterniond(d->orientation[0], d->orientation[1], d->orientation[2], d->orientation[3]);
  state.velocity = Eigen::Vector3d(d->velocity[0], d->velocity[1], d->velocity[2]);
  state.angular_velocity =
      Eigen::Vector3d(d->angular_velocity[0], d->angular_velocity[1], d->angular_velocity[2]);
  state.buttons = d->buttons;
  s->device->Set(state);
  const bool ticked = !s->done && s->scheduler->Tick(d->time);
  if (!ticked) {
    s->done = true;
    for (int k = 0; k < 3; ++k) out->force[k] = out->torque[k] = 0.0;
    return FITFEEL_DONE;
  }
  const Wrench& w = s->device->written();
  for (int k = 0; k < 3; ++k) {
    out->force[k] = w.force[k];
    out->torque[k] = w.torque[k];
  }
  return FITFEEL_OK;
}

int fitfeel_contact_state(const fitfeel_scene* s, fitfeel_contact* out) {
  if (s == nullptr || out == nullptr) return FITFEEL_INVALID_ARGUMENT;
  *out = fitfeel_contact{};
  // The trace is sized for the whole run before it starts: the last tick is at ticks_done - 1.
  const auto& trace = s->scheduler->trace();
  const std::uint64_t done = s->scheduler->ticks_done();
  if (done == 0 || done > trace.size()) return FITFEEL_OK;
  const fitfeel::TickRecord& r = trace[done - 1];
  out->stage = r.stage == fitfeel::StageId::kConstrained ? 1 : 0;
  out->engaged = r.contact.engaged ? 1 : 0;
  out->interference = r.contact.interference ? 1 : 0;
  out->depth = r.pose.depth;
  out->max_interference = r.contact.max_interference;
  out->interference_volume = r.contact.interference_volume;
  for (int k = 0; k < 3; ++k) out->model_force[k] = r.wrench.force[k];
  return FITFEEL_OK;
}

uint64_t fitfeel_ticks(const fitfeel_scene* s) {
  return s == nullptr ? 0 : s->scheduler->ticks_done();
}

int fitfeel_pressure_map(fitfeel_scene* s, double* pressure, int capacity, int* rows,
                         int* columns) {
  if (s == nullptr || rows == nullptr || columns == nullptr) return FITFEEL_INVALID_ARGUMENT;
  s->error.clear();
  const fitfeel::SurfaceGrid& grid = s->prepared.inner_sms->grid;
  *rows = grid.rows;
  *columns = grid.columns;
  if (pressure == nullptr || capacity < grid.size()) {
    s->error = "fitfeel_pressure_map: room for " + std::to_string(grid.size()) +
               " values needed, " + std::to_string(capacity) + " given";
    return FITFEEL_INVALID_ARGUMENT;
  }
  try {
    const double k = s->prepared.law->PressurePerInterference();
    fitfeel::MatingPose pose;
    const std::uint64_t done = s->scheduler->ticks_done();
    if (done > 0) pose = s->scheduler->trace()[done - 1].pose;
    Eigen::VectorXd delta;
    s->prepared.analyzer->InterferenceMap(fitfeel::AnalyzerPose(pose, s->scene.moving), &delta);
    for (int c = 0; c < grid.size(); ++c) pressure[c] = k * delta(c);
    return FITFEEL_OK;
  } catch (const std::exception& e) {
    s->error = e.what();
    return FITFEEL_ERROR;
  }
}

int fitfeel_write_outputs(fitfeel_scene* s, const char* dir) {
  if (s == nullptr) return FITFEEL_INVALID_ARGUMENT;
  s->error.clear();
  if (dir == nullptr) {
    s->error = "fitfeel_write_outputs: dir is null";
    return FITFEEL_INVALID_ARGUMENT;
  }
  try {
    fitfeel::RunInfo info = fitfeel::MakeRunInfo(s->scene, s->prepared);
    info.device = "host (C interface)";
    const std::uint64_t done = s->scheduler->ticks_done();
    const auto& trace = s->scheduler->trace();
    const std::vector<fitfeel::TickRecord> stepped(
        trace.begin(), trace.begin() + static_cast<std::ptrdiff_t>(std::min<std::uint64_t>(
                                           done, trace.size())));
    fitfeel::WriteOutputs(dir, info, stepped, s->scheduler->StatsSoFar());
    return FITFEEL_OK;
  } catch (const fitfeel::ScenarioError& e) {
    s->error = e.what();
    return FITFEEL_SCENARIO_ERROR;
  } catch (const std::exception& e) {
    s->error = e.what();
    return FITFEEL_ERROR;
  }
}

const char* fitfeel_last_error(const fitfeel_scene* s) {
  return s == nullptr ? thread_error.c_str() : s->error.c_str();
}

const char* fitfeel_thread_last_error(void) { return thread_error.c_str(); }

void fitfeel_close(fitfeel_scene* s) { delete s; }

}  // extern "C"
