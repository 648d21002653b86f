// The `features` section: the mating features that join the same two bodies (docs/assemblies.md).

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framework/collision/coarse_mesh.h"
#include "framework/core/quantity.h"
#include "framework/scenario/joint_frame.h"
#include "framework/scenario/scene_sections.h"

namespace fitfeel::scenario {
namespace {

// Features closer than this across their cross-sections overlap: a micrometre is below any
// machined part's size tolerance, and keeps two solids that only touch (a key on its shaft) apart.
constexpr double kOverlapTolerance = 1e-6;
// A feature more than a metre off the datum axis belongs to another assembly.
constexpr double kMaxPlacement = 1.0;

// The convex hull of points in the (x, z) cross-section, counter-clockwise (Andrew's monotone
// chain).
std::vector<Eigen::Vector2d> Hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0.0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// How far two convex polygons overlap: the least, over the separating axes of their edges, of
// the overlap of their projections (negative: a gap between them).
double Overlap(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double least = std::numeric_limits<double>::infinity();
  for (const std::vector<Eigen::Vector2d>* poly : {&a, &b}) {
    const std::size_t n = poly->size();
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d edge = (*poly)[(i + 1) % n] - (*poly)[i];
      if (edge.norm() == 0.0) continue;
      const Eigen::Vector2d axis = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
      double a_lo = INFINITY, a_hi = -INFINITY, b_lo = INFINITY, b_hi = -INFINITY;
      for (const Eigen::Vector2d& v : a) {
        a_lo = std::min(a_lo, v.dot(axis));
        a_hi = std::max(a_hi, v.dot(axis));
      }
      for (const Eigen::Vector2d& v : b) {
        b_lo = std::min(b_lo, v.dot(axis));
        b_hi = std::max(b_hi, v.dot(axis));
      }
      least = std::min(least, std::min(a_hi, b_hi) - std::max(a_lo, b_lo));
    }
  }
  return least;
}

// The cross-section of a feature's inner solid (the shaft, key or pin) where the feature places
// it, from its coarse mesh; empty when the surface type has none.
std::vector<Eigen::Vector2d> InnerSection(const MatingFeature& feature) {
  const CoarseMeshes meshes = feature.surface->MakeCoarseMeshes(feature.inner, feature.outer);
  const double c = std::cos(feature.placement.angle), s = std::sin(feature.placement.angle);
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& v : meshes.inner.vertices) {
    points.push_back(feature.placement.at + TurnAboutAxis(Eigen::Vector2d(v.x(), v.z()), c, s));
  }
  return Hull(std::move(points));
}

FeaturePlacement ParsePlacement(const ConfigNode& node, bool datum, const std::string& inner,
                                const std::string& outer) {
  FeaturePlacement placement;
  const auto refuse_on_datum = [&](const char* key) {
    if (datum && node.Has(key)) {
      node.Child(key).Fail("no `" + std::string(key) +
                               "` on the first feature: it is the datum the others are placed from",
                           node.Child(key).Describe());
    }
  };
  for (const char* key : {"at", "engages_after", "position"}) refuse_on_datum(key);
  if (std::optional<ConfigNode> at = node.Find("at")) {
    if (!at->is_map()) at->Fail("a map {x, z} of lengths", at->Describe());
    at->ExpectOnlyKeys({"x", "z"});
    const auto coordinate = [&](const char* key) {
      return at->Child(key).AsQuantityIn(Dimension::kLength, -kMaxPlacement, kMaxPlacement);
    };
    placement.at = Eigen::Vector2d(coordinate("x"), coordinate("z"));
  }
  if (std::optional<ConfigNode> angle = node.Find("angle")) {
    placement.angle = angle->AsQuantityIn(Dimension::kAngle, -M_PI, M_PI);
  }
  if (std::optional<ConfigNode> after = node.Find("engages_after")) {
    placement.engages_after = after->AsQuantityIn(Dimension::kLength, 0.0, kMaxPlacement);
  }
  if (std::optional<ConfigNode> position = node.Find("position")) {
    if (!position->is_map()) {
      position->Fail("a map from part name to its position tolerance (a length)",
                     position->Describe());
    }
    position->ExpectOnlyKeys({inner, outer});
    const auto tolerance = [&](const std::string& part) {
      std::optional<ConfigNode> value = position->Find(part);
      return value ? value->AsQuantityIn(Dimension::kLength, 0.0, 1e-3) : 0.0;
    };
    placement.inner_position = tolerance(inner);
    placement.outer_position = tolerance(outer);
  }
  return placement;
}

}  // namespace

void ParseFeatures(const ConfigNode& root, const ConfigNode& duration,
                   const PluginRegistry& registry, const LoadOptions& options, Scene* scene) {
  const ConfigNode node = root.Child("features");
  if (!node.is_map())
    node.Fail("a map from feature name to its surface and parts", node.Describe());
  const std::vector<std::string> names = node.Keys();
  if (names.size() < 2 || names.size() > static_cast<std::size_t>(kMaxJointFeatures)) {
    node.Fail("2 to " + std::to_string(kMaxJointFeatures) +
                  " features (one feature: `surface` and `parts` instead)",
              std::to_string(names.size()));
  }
  if (scene->part_motion.radial == RadialMotion::kDynamic) {
    root.Child("part_motion")
        .Child("radial")
        .Fail("held or quasi_static in a several-feature scene", "dynamic");
  }
  // Each feature's `model` section (its own, else the scene's): parsed, then admitted below.
  std::vector<ConfigNode> model_nodes;
  const ConfigNode moving = root.Child("moving");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const ConfigNode f = node.Child(names[i]);
    if (!IsPlainName(names[i])) {
      f.Fail("a feature name of letters, digits, '_', '-' or '.'", "'" + names[i] + "'");
    }
    if (!f.is_map()) f.Fail("a map with surface, parts and the feature's placement", f.Describe());
    f.ExpectOnlyKeys({"surface", "parts", "model", "at", "angle", "engages_after", "position"});
    MatingFeature feature;
    feature.name = names[i];
    const ConfigNode surface = f.Child("surface");
    feature.surface = ResolveSurface(surface, registry, options, &feature.surface_id);
    if (feature.surface->rotational()) {
      surface.Fail(
          "a surface whose parts slide along the axis (a joint of several features "
          "advances along one axis)",
          surface.Describe() + ", whose parts turn about a centre or screw along the axis");
    }
    const ConfigNode parts_node = f.Child("parts");
    // Every feature joins the moving body to the fixed one: refused at the feature's parts, not at
    // `moving`, where they name another.
    if (parts_node.is_map() && !parts_node.Has(moving.AsString())) {
      parts_node.Fail("the moving part '" + moving.AsString() + "' among the feature's parts",
                      "the parts " + JoinList(parts_node.Keys()));
    }
    Parts parts = ParseParts(parts_node, moving, *feature.surface, feature.surface_id);
    const std::string moving_body = moving.AsString();
    const std::string fixed_body =
        parts.inner.name == moving_body ? parts.outer.name : parts.inner.name;
    if (i == 0) {
      scene->moving_body = moving_body;
      scene->fixed_body = fixed_body;
    } else if (fixed_body != scene->fixed_body) {
      parts_node.Fail("the parts '" + scene->fixed_body + "' and '" + scene->moving_body +
                          "' of the first feature (each feature joins the same two parts)",
                      "'" + parts.inner.name + "' and '" + parts.outer.name + "'");
    }
    feature.moving = parts.moving;
    const std::optional<ConfigNode> own_model = f.Find("model");
    if (!own_model && !root.Has("model")) {
      f.Fail("a `model` of the feature's own or the scene's", "neither");
    }
    model_nodes.push_back(own_model ? *own_model : root.Child("model"));
    feature.model = ParseModel(model_nodes.back(), *feature.surface, feature.surface_id, parts);
    feature.placement = ParsePlacement(f, i == 0, parts.inner.name, parts.outer.name);
    feature.inner = std::move(parts.inner);
    feature.outer = std::move(parts.outer);
    // A feature that meets only after the datum's parts have passed each other lies outside
    // them along the axis: nothing of the joint would hold while it engages.
    if (i > 0) {
      const MatingFeature& datum = scene->features.front();
      const double stroke =
          datum.inner.geometry->mating_length() + datum.outer.geometry->mating_length();
      if (!(feature.placement.engages_after < stroke)) {
        const ConfigNode after = f.Child("engages_after");
        after.Fail("a place within the first feature's stroke (its parts' lengths together, " +
                       FormatQuantity(stroke, Dimension::kLength) + ")",
                   after.Describe());
      }
    }
    scene->features.push_back(std::move(feature));
  }

  // Features that overlap across the axis: the inner solids' cross-sections (shafts, keys, pins).
  std::vector<std::vector<Eigen::Vector2d>> sections;
  for (const MatingFeature& feature : scene->features) sections.push_back(InnerSection(feature));
  for (std::size_t i = 0; i < sections.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (sections[i].size() < 3 || sections[j].size() < 3) continue;
      const double overlap = Overlap(sections[i], sections[j]);
      if (overlap > kOverlapTolerance) {
        const ConfigNode f = node.Child(names[i]);
        const ConfigNode key = f.Has("at") ? f.Child("at") : f;
        key.Fail(
            "a place where the feature's " + scene->features[i].inner.name +
                " side does not overlap feature '" + names[j] + "'",
            "their cross-sections overlapping by " + FormatQuantity(overlap, Dimension::kLength));
      }
    }
  }

  // A scene-wide model that no feature takes would be read by nothing: refused, not ignored.
  if (std::optional<ConfigNode> model = root.Find("model")) {
    bool used = false;
    for (const std::string& name : names) used = used || !node.Child(name).Has("model");
    if (!used) {
      model->Fail("no scene-wide `model` where every feature gives its own",
                  "a model no feature uses");
    }
  }

  const MatingFeature& datum = scene->features.front();
  scene->surface = datum.surface;
  scene->surface_id = datum.surface_id;
  scene->inner = datum.inner;
  scene->outer = datum.outer;
  scene->moving = datum.moving;
  scene->model = datum.model;

  for (std::size_t i = 0; i < scene->features.size(); ++i) {
    const MatingFeature& feature = scene->features[i];
    const SceneCost cost = CheckPrepare(model_nodes[i], duration, *feature.surface, feature.inner,
                                        feature.outer, feature.model, scene->run, options);
    if (i == 0) {
      scene->cost = cost;
      continue;
    }
    // The run's buffers and outputs are the scene's once; the preparations add up.
    scene->cost.inner_cells += cost.inner_cells;
    scene->cost.outer_cells += cost.outer_cells;
    scene->cost.depth_steps += cost.depth_steps;
    scene->cost.prepare_bytes += cost.prepare_bytes;
    scene->cost.prepare_seconds += cost.prepare_seconds;
    scene->cost.law_prepare_seconds += cost.law_prepare_seconds;
  }
  // Each feature fits the thresholds alone; so must the scene's preparation of all of them.
  if (!options.allow_large) {
    SceneCost admitted = scene->cost;
    if (!options.writes_outputs) admitted.output_bytes = 0.0;
    if (const std::optional<CostRefusal> refusal = LargeCostRefusal(admitted)) {
      node.Fail(refusal->expected + " (all the features together)",
                node.Describe() + ": " + refusal->found);
    }
  }
}

}  // namespace fitfeel::scenario
