#pragma once

// A test helper for analyzers whose assembly space is exact at every pose: `polygon` (from
// ContactAnalyzer::AssemblySpace at `pose`) must hold exactly the contact-free offsets of
// `reference` (a sharp-contact analyzer): nothing touches 1 % inside towards each vertex from the
// vertex mean, something touches 1 % beyond it.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "framework/model/contact_analyzer.h"

namespace fitfeel::test_support {

inline void ExpectPolygonIsTheContactFreeSpace(const ContactAnalyzer& reference,
                                               const MatingPose& pose,
                                               const std::vector<Eigen::Vector2d>& polygon,
                                               const std::string& where) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& v : polygon) centre += v / static_cast<double>(polygon.size());
  for (const auto& v : polygon) {
    MatingPose inside = pose, beyond = pose;
    inside.offset = centre + 0.99 * (v - centre);
    beyond.offset = centre + 1.01 * (v - centre);
    ContactState contact;
    reference.Evaluate(inside, &contact);
    EXPECT_EQ(contact.interference_volume, 0.0) << where << ", inside towards " << v.transpose();
    reference.Evaluate(beyond, &contact);
    EXPECT_GT(contact.interference_volume, 0.0) << where << ", beyond " << v.transpose();
  }
}

}  // namespace fitfeel::test_support
