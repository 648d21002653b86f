#pragma once

namespace fitfeel {

// The most mating features one scene joins: a tick keeps each feature's force in a fixed-size
// array, so the count is bounded at compile time.
inline constexpr int kMaxJointFeatures = 8;

}  // namespace fitfeel
