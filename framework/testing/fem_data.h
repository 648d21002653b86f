#pragma once

// The committed CalculiX reference (tools/fem/data), read by the tests of every surface that has
// one. Uses FITFEEL_TEST_SOURCE_DIR: test targets only.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fitfeel::test_support {

// Column `column` (0 = the case's name) of the row of case `name` in tools/fem/data/`file`;
// throws (a failure of the calling test) if there is none.
inline double FemValue(const std::string& file, const std::string& name, int column) {
  const std::string path = std::string(FITFEEL_TEST_SOURCE_DIR) + "/tools/fem/data/" + file;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(name + ",", 0) != 0) continue;
    std::stringstream fields(line);
    std::string value;
    for (int c = 0; c <= column; ++c) {
      if (!std::getline(fields, value, ',')) {
        throw std::runtime_error("case " + name + " in " + path + " has no column " +
                                 std::to_string(column));
      }
    }
    return std::stod(value);
  }
  throw std::runtime_error("no case " + name + " in " + path);
}

// The bursting force B = integral of p n_r dA (N) of the case `name` in
// tools/fem/data/axisymmetric.csv.
inline double AxisymmetricFemForce(const std::string& name) {
  return FemValue("axisymmetric.csv", name, 1);
}

}  // namespace fitfeel::test_support
