#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/chamfer.h"
#include "framework/model/gps_spec.h"

namespace fitfeel::cylindrical {

// Nominal geometry of one cylindrical mating surface. The mating diameter is the part's nominal
// size (PartSpec::size.nominal); the rest comes from the part's `geometry` node.
class CylindricalGeometry final : public Geometry {
 public:
  CylindricalGeometry(Role role, double diameter, double length, double outer_diameter,
                      double bore_diameter)
      : role_(role),
        diameter_(diameter),
        length_(length),
        outer_diameter_(outer_diameter),
        bore_diameter_(bore_diameter) {}

  Role role() const { return role_; }
  double diameter() const { return diameter_; }              // mating diameter d1, m
  double length() const { return length_; }                  // length of the mating surface, m
  double outer_diameter() const { return outer_diameter_; }  // outer part: hub outer d2, m
  double bore_diameter() const {
    return bore_diameter_;
  }  // inner part: bore of a hollow shaft (0 = solid), m
  const Chamfer& chamfer() const { return chamfer_; }  // at the mating end
  void set_chamfer(const Chamfer& chamfer) { chamfer_ = chamfer; }

 protected:
  double DoNominalArea() const override;
  double DoMatingLength() const override { return length_; }
  std::string DoDescribe() const override;

 private:
  Role role_;
  double diameter_;
  double length_;
  double outer_diameter_;
  double bore_diameter_;
  Chamfer chamfer_;
};

// Parses one part's `geometry` node: `length` (> 0) for both parts; `outer_diameter` (the hub's
// d2, > d, required) for the outer part; optional `bore_diameter` (hollow shaft, 0 <= di < d)
// for the inner part; optional `chamfer` at the mating end, a length (45 degrees, ISO 13715's
// "C" edge) or {length, angle}, shorter than the part and narrower than its wall. d is
// part.size.nominal. Throws ScenarioError at the offending key.
std::shared_ptr<const CylindricalGeometry> ParseCylindricalGeometry(const PartSpec& part,
                                                                    const ConfigNode& geometry);

// Both parts of a cylindrical fit share one nominal diameter; throws ScenarioError at `pair_node`.
void CheckCylindricalPair(const PartSpec& inner, const PartSpec& outer,
                          const ConfigNode& pair_node);

}  // namespace fitfeel::cylindrical
