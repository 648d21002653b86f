#include "framework/study/study_record.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/core/os_reason.h"

namespace fitfeel::study {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

int Column(const std::vector<std::string>& header, const std::string& name, const fs::path& file) {
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == name) return static_cast<int>(k);
  }
  throw UserError(file.string() + ":1: no column '" + name + "' in the header");
}

double Cell(const std::vector<std::string>& cells, int column, const fs::path& file, int line) {
  double value = 0.0;
  const std::string& text = cells.at(static_cast<std::size_t>(column));
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw UserError(file.string() + ":" + std::to_string(line) + ": expected a finite number in column " +
                    std::to_string(column + 1) + ", found '" + text + "'");
  }
  return value;
}

}  // namespace

StudyRecord LoadStudy(const fs::path& dir) {
  StudyRecord record;
  record.dir = dir;
  const fs::path json_file = dir / "study.json";
  errno = 0;
  std::ifstream json_in(json_file);
  const int json_error = errno;
  if (!json_in) {
    throw UserError("cannot read '" + json_file.string() + "': " + OsReason(json_error) +
                    " (is it a study folder?)");
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(json_in);
    record.scenario = j.at("scenario").get<std::string>();
    record.probability_of_interference = j.at("probability_of_interference").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw UserError(json_file.string() + ": not a study summary: " + e.what());
  }
  const fs::path csv = dir / "pairs.csv";
  errno = 0;
  std::ifstream in(csv);
  const int csv_error = errno;
  if (!in) throw UserError("cannot read '" + csv.string() + "': " + OsReason(csv_error));
  std::string line;
  if (!std::getline(in, line)) throw UserError(csv.string() + ":1: empty file, expected a header");
  const std::vector<std::string> header = Cells(line);
  const int mean = Column(header, "axial_mean_N", csv);
  const int max = Column(header, "axial_max_N", csv);
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> cells = Cells(line);
    if (cells.size() != header.size()) {
      throw UserError(csv.string() + ":" + std::to_string(number) + ": expected " +
                      std::to_string(header.size()) + " cells, found " +
                      std::to_string(cells.size()));
    }
    record.axial_mean_N.push_back(Cell(cells, mean, csv, number));
    record.axial_max_N.push_back(Cell(cells, max, csv, number));
  }
  if (record.axial_mean_N.empty()) throw UserError(csv.string() + ": no pairs");
  return record;
}

}  // namespace fitfeel::study
