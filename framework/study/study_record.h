#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel::study {

// A finished study read back from its folder (pairs.csv and study.json), for charts.
struct StudyRecord {
  std::filesystem::path dir;
  std::string scenario;
  std::vector<double> axial_mean_N;  // one per pair, in pair order
  std::vector<double> axial_max_N;
  double probability_of_interference = 0.0;
};

// Throws UserError naming the file (and line for pairs.csv) for a missing or broken folder.
FITFEEL_API StudyRecord LoadStudy(const std::filesystem::path& dir);

}  // namespace fitfeel::study
