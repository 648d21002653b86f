#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/render_mesh.h"
#include "framework/view/view_sample.h"

namespace fitfeel::view {

// The viewer's binary WebSocket frames (README.md, "Frame format"): little-endian, an 8-byte
// header (magic "FFVW", u16 version, u16 kind), then the kind's body. Floats are IEEE f32 in SI
// units except where the README says otherwise.
inline constexpr std::uint16_t kFrameVersion = 1;
enum class FrameKind : std::uint16_t { kMesh = 1, kState = 2, kHistory = 3 };
inline constexpr std::size_t kHeaderBytes = 8;
inline constexpr std::size_t kStateFixedBytes = 96;  // header and the state's fixed fields
inline constexpr std::size_t kHistoryRowFloats = 12;

// Flags of a state frame.
enum StateFlag : std::uint8_t {
  kEngaged = 1,
  kInterference = 2,
  kGuardFault = 4,
  kRunFinished = 8,
  kAssemblySpaceKnown = 16,  // the surface type describes its assembly space (maybe empty)
};

// What a state frame carries beside the sample: the contact pressure of every cell of the inner
// part's grid, quantised to 0..255 of `pressure_max` (Pa), and the assembly space polygon.
struct StateExtras {
  double pressure_max = 0.0;          // Pa; 0 with no pressure
  std::vector<std::uint8_t> pressure;  // one per inner cell, or empty (no pressure map)
  std::vector<Eigen::Vector2d> assembly_space;  // (x, z), m
  bool assembly_space_known = false;
  bool run_finished = false;
  std::uint64_t dropped = 0;  // samples the ring had no room for
};

// Quantises a pressure map (Pa, >= 0) to 0..255 of its maximum, which it returns (0 for an empty or
// all-zero map, whose cells are then 0). Negative and non-finite cells count as 0.
FITFEEL_API double QuantisePressure(const Eigen::VectorXd& pressure,
                                    std::vector<std::uint8_t>* out);

// Mesh frame of one part (0 inner, 1 outer) of the scene's `feature` (its index in
// Scene::features; 0 for the datum feature and for a one-feature scene). `variation` holds V per
// cell (m); an empty mesh is encoded with zero cells and the placeholder flag. Throws UserError for
// sizes that disagree or a feature index over 65535.
FITFEEL_API std::string EncodeMeshFrame(int part, const RenderMesh& mesh,
                                        const Eigen::VectorXd& variation, int feature = 0);
// State frame. Throws UserError for more than 65535 polygon vertices.
FITFEEL_API std::string EncodeStateFrame(const ViewSample& sample, const StateExtras& extras);
// History frame: one row of kHistoryRowFloats f32 per sample.
FITFEEL_API std::string EncodeHistoryFrame(const std::vector<ViewSample>& samples);

// Decoded mesh frame (tests read frames back with it): the corners and directions at f32
// precision.
struct DecodedMesh {
  int part = 0;
  int feature = 0;
  bool placeholder = false;
  RenderMesh mesh;
  Eigen::VectorXd variation;
};
// Throws UserError for a frame that is not a well-formed mesh frame.
FITFEEL_API DecodedMesh DecodeMeshFrame(std::string_view frame);

// Decoded state frame (tests and tools read frames back with it).
struct DecodedState {
  ViewSample sample;  // as transmitted (f32 precision)
  std::uint8_t flags = 0;
  StateExtras extras;
};
// Throws UserError for a frame that is not a well-formed state frame.
FITFEEL_API DecodedState DecodeStateFrame(std::string_view frame);

}  // namespace fitfeel::view
