#include "framework/view/frame_codec.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "framework/core/error.h"

namespace fitfeel::view {
namespace {

static_assert(std::endian::native == std::endian::little,
              "frames are written in the host's byte order, which must be little-endian");

class Writer {
 public:
  explicit Writer(std::size_t reserve) { out_.reserve(reserve); }
  template <typename T>
  void Put(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  void F32(double value) { Put(static_cast<float>(value)); }
  void Header(FrameKind kind) {
    out_.append("FFVW", 4);
    Put<std::uint16_t>(kFrameVersion);
    Put(static_cast<std::uint16_t>(kind));
  }
  std::size_t size() const { return out_.size(); }
  std::string Take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <typename T>
  T Get() {
    if (pos_ + sizeof(T) > in_.size()) {
      throw UserError("viewer frame: truncated at byte " + std::to_string(pos_) + " of " +
                      std::to_string(in_.size()));
    }
    T value;
    std::memcpy(&value, in_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  double F32() { return Get<float>(); }
  std::size_t pos() const { return pos_; }
  std::size_t remaining() const { return in_.size() - pos_; }

 private:
  std::string_view in_;
  std::size_t pos_ = 0;
};

// Pose and wrench: the same order in state frames and history rows.
void PutPoseAndWrench(Writer& w, const ViewSample& s) {
  w.F32(s.depth);
  w.F32(s.offset_x);
  w.F32(s.offset_z);
  w.F32(s.angle);
  for (double f : s.force) w.F32(f);
  for (double t : s.torque) w.F32(t);
}

}  // namespace

double QuantisePressure(const Eigen::VectorXd& pressure, std::vector<std::uint8_t>* out) {
  out->assign(static_cast<std::size_t>(pressure.size()), 0);
  double max = 0.0;
  for (Eigen::Index k = 0; k < pressure.size(); ++k) {
    if (std::isfinite(pressure[k])) max = std::max(max, pressure[k]);
  }
  if (!(max > 0.0)) return 0.0;
  for (Eigen::Index k = 0; k < pressure.size(); ++k) {
    const double p = std::isfinite(pressure[k]) ? std::max(pressure[k], 0.0) : 0.0;
    (*out)[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::lround(255.0 * p / max));
  }
  return max;
}

std::string EncodeMeshFrame(int part, const RenderMesh& mesh, const Eigen::VectorXd& variation,
                            int feature) {
  if (part != 0 && part != 1) throw UserError("viewer mesh frame: part must be 0 or 1");
  if (feature < 0 || feature > std::numeric_limits<std::uint16_t>::max()) {
    throw UserError("viewer mesh frame: feature index " + std::to_string(feature) +
                    " outside 0..65535");
  }
  const std::size_t cells = mesh.directions.size();
  if (mesh.corners.size() != 4 * cells ||
      (cells > 0 && static_cast<std::size_t>(variation.size()) != cells)) {
    throw UserError("viewer mesh frame: " + std::to_string(mesh.corners.size()) + " corners, " +
                    std::to_string(cells) + " directions and " +
                    std::to_string(variation.size()) + " variations do not match");
  }
  if (cells > std::numeric_limits<std::uint32_t>::max() / 4) {
    throw UserError("viewer mesh frame: too many cells");
  }
  Writer w(kHeaderBytes + 8 + cells * 64);
  w.Header(FrameKind::kMesh);
  w.Put<std::uint8_t>(static_cast<std::uint8_t>(part));
  w.Put<std::uint8_t>(cells == 0 ? 1 : 0);  // placeholder: no render mesh
  w.Put<std::uint16_t>(static_cast<std::uint16_t>(feature));
  w.Put<std::uint32_t>(static_cast<std::uint32_t>(cells));
  for (const auto& c : mesh.corners) {
    for (int i = 0; i < 3; ++i) w.F32(c[i]);
  }
  for (const auto& d : mesh.directions) {
    for (int i = 0; i < 3; ++i) w.F32(d[i]);
  }
  for (std::size_t k = 0; k < cells; ++k) w.F32(variation[static_cast<Eigen::Index>(k)]);
  return w.Take();
}

std::string EncodeStateFrame(const ViewSample& s, const StateExtras& x) {
  if (x.assembly_space.size() > std::numeric_limits<std::uint16_t>::max()) {
    throw UserError("viewer state frame: assembly space of more than 65535 vertices");
  }
  if (x.pressure.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw UserError("viewer state frame: pressure map too large");
  }
  Writer w(kStateFixedBytes + 8 * x.assembly_space.size() + x.pressure.size());
  w.Header(FrameKind::kState);
  w.Put<double>(s.time);
  w.Put<std::uint32_t>(static_cast<std::uint32_t>(s.tick));
  w.Put<std::uint32_t>(static_cast<std::uint32_t>(std::min<std::uint64_t>(
      x.dropped, std::numeric_limits<std::uint32_t>::max())));
  PutPoseAndWrench(w, s);
  w.F32(s.offset_distance);
  w.F32(s.offset_angle);
  w.F32(s.assembly_extent);
  w.F32(s.penetration);
  w.F32(s.max_interference);
  std::uint8_t flags = 0;
  if (s.engaged) flags |= kEngaged;
  if (s.interference) flags |= kInterference;
  if (s.guard_fault) flags |= kGuardFault;
  if (x.run_finished) flags |= kRunFinished;
  if (x.assembly_space_known) flags |= kAssemblySpaceKnown;
  w.Put<std::uint8_t>(s.stage);
  w.Put<std::uint8_t>(flags);
  w.Put<std::uint16_t>(static_cast<std::uint16_t>(x.assembly_space.size()));
  w.F32(x.pressure_max);
  w.Put<std::uint32_t>(static_cast<std::uint32_t>(x.pressure.size()));
  if (w.size() != kStateFixedBytes) throw std::logic_error("viewer state frame layout");
  for (const auto& v : x.assembly_space) {
    w.F32(v.x());
    w.F32(v.y());
  }
  std::string out = w.Take();
  out.append(reinterpret_cast<const char*>(x.pressure.data()), x.pressure.size());
  return out;
}

std::string EncodeHistoryFrame(const std::vector<ViewSample>& samples) {
  if (samples.size() > std::numeric_limits<std::uint32_t>::max() / 64) {
    throw UserError("viewer history frame: too many rows");
  }
  Writer w(kHeaderBytes + 4 + samples.size() * kHistoryRowFloats * 4);
  w.Header(FrameKind::kHistory);
  w.Put<std::uint32_t>(static_cast<std::uint32_t>(samples.size()));
  for (const auto& s : samples) {
    w.F32(s.time);
    PutPoseAndWrench(w, s);
    w.F32(s.stage);
  }
  return w.Take();
}

namespace {

// Checks the magic, the version and the kind of a frame's header, which it reads.
void ReadHeader(Reader& r, std::string_view frame, FrameKind expected, const char* what) {
  if (frame.size() < kHeaderBytes || frame.substr(0, 4) != "FFVW") {
    throw UserError(std::string("viewer frame: not a ") + what + " frame (too short or no magic)");
  }
  r.Get<std::uint32_t>();
  const auto version = r.Get<std::uint16_t>();
  const auto kind = r.Get<std::uint16_t>();
  if (version != kFrameVersion || kind != static_cast<std::uint16_t>(expected)) {
    throw UserError("viewer frame: version " + std::to_string(version) + " kind " +
                    std::to_string(kind) + ", expected a version " +
                    std::to_string(kFrameVersion) + " " + what + " frame");
  }
}

}  // namespace

DecodedMesh DecodeMeshFrame(std::string_view frame) {
  Reader r(frame);
  ReadHeader(r, frame, FrameKind::kMesh, "mesh");
  DecodedMesh d;
  d.part = r.Get<std::uint8_t>();
  d.placeholder = r.Get<std::uint8_t>() != 0;
  d.feature = r.Get<std::uint16_t>();
  const std::size_t cells = r.Get<std::uint32_t>();
  if (r.remaining() != 64 * cells) {
    throw UserError("viewer frame: " + std::to_string(r.remaining()) + " bytes after the mesh " +
                    "header, expected " + std::to_string(64 * cells));
  }
  const auto vector = [&r] {
    const double x = r.F32(), y = r.F32();
    return Eigen::Vector3d(x, y, r.F32());
  };
  for (std::size_t k = 0; k < 4 * cells; ++k) d.mesh.corners.push_back(vector());
  for (std::size_t k = 0; k < cells; ++k) d.mesh.directions.push_back(vector());
  d.variation.resize(static_cast<Eigen::Index>(cells));
  for (std::size_t k = 0; k < cells; ++k) d.variation[static_cast<Eigen::Index>(k)] = r.F32();
  return d;
}

DecodedState DecodeStateFrame(std::string_view frame) {
  Reader r(frame);
  if (frame.size() < kStateFixedBytes || frame.substr(0, 4) != "FFVW") {
    throw UserError("viewer frame: not a state frame (too short or no magic)");
  }
  r.Get<std::uint32_t>();
  const auto version = r.Get<std::uint16_t>();
  const auto kind = r.Get<std::uint16_t>();
  if (version != kFrameVersion || kind != static_cast<std::uint16_t>(FrameKind::kState)) {
    throw UserError("viewer frame: version " + std::to_string(version) + " kind " +
                    std::to_string(kind) + ", expected a version " +
                    std::to_string(kFrameVersion) + " state frame");
  }
  DecodedState d;
  ViewSample& s = d.sample;
  s.time = r.Get<double>();
  s.tick = r.Get<std::uint32_t>();
  d.extras.dropped = r.Get<std::uint32_t>();
  s.depth = r.F32();
  s.offset_x = r.F32();
  s.offset_z = r.F32();
  s.angle = r.F32();
  for (double& f : s.force) f = r.F32();
  for (double& t : s.torque) t = r.F32();
  s.offset_distance = r.F32();
  s.offset_angle = r.F32();
  s.assembly_extent = r.F32();
  s.penetration = r.F32();
  s.max_interference = r.F32();
  s.stage = r.Get<std::uint8_t>();
  d.flags = r.Get<std::uint8_t>();
  const std::size_t vertices = r.Get<std::uint16_t>();
  d.extras.pressure_max = r.F32();
  const std::size_t cells = r.Get<std::uint32_t>();
  if (r.remaining() != 8 * vertices + cells) {
    throw UserError("viewer frame: " + std::to_string(r.remaining()) + " bytes after the fixed " +
                    "fields, expected " + std::to_string(8 * vertices + cells));
  }
  for (std::size_t k = 0; k < vertices; ++k) {
    const double x = r.F32();
    d.extras.assembly_space.emplace_back(x, r.F32());
  }
  d.extras.pressure.assign(frame.begin() + static_cast<std::ptrdiff_t>(r.pos()), frame.end());
  s.engaged = d.flags & kEngaged;
  s.interference = d.flags & kInterference;
  s.guard_fault = d.flags & kGuardFault;
  d.extras.run_finished = d.flags & kRunFinished;
  d.extras.assembly_space_known = d.flags & kAssemblySpaceKnown;
  return d;
}

}  // namespace fitfeel::view
