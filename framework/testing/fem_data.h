#pragma once

// The committed CalculiX reference of the axisymmetric cases (tools/fem/axisymmetric.py), read
// by the tests of every surface that has one. Uses FITFEEL_TEST_SOURCE_DIR: test targets only.
#include <fstream>
#include <stdexcept>
#include <string>

namespace fitfeel::test_support {

// The bursting force B = integral of p n_r dA (N) of the case `name` in
// tools/fem/data/axisymmetric.csv; throws (a failure of the calling test) if there is none.
inline double AxisymmetricFemForce(const std::string& name) {
  const std::string path =
      std::string(FITFEEL_TEST_SOURCE_DIR) + "/tools/fem/data/axisymmetric.csv";
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(name + ",", 0) == 0) return std::stod(line.substr(name.size() + 1));
  }
  throw std::runtime_error("no case " + name + " in " + path);
}

}  // namespace fitfeel::test_support
