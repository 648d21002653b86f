#pragma once

// The nominal size steps of ISO 286-1 up to 500 mm. A step runs from "above" its lower bound up to
// and including its upper bound, so a size on a boundary belongs to the lower step (30 mm is in
// 18-30 mm). The first step is "up to and including 3 mm".

#include <array>

namespace fitfeel::iso286::tables {

// Main steps (ISO 286-1 Table 1): the standard tolerances IT and the fundamental deviations that
// do not change inside a main step are given per main step.
inline constexpr int kMainStepCount = 13;
inline constexpr std::array<double, kMainStepCount> kMainStepUpperMm = {
    3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500};

// Intermediate steps: the main steps above 10 mm split in two or three, used by the fundamental
// deviations a-c and r-zc (A-C, R-ZC). The shaft deviation table is laid out on these rows; a
// value that holds for a whole main step is repeated on each of its intermediate rows, as the
// standard's merged cells show it.
inline constexpr int kFineStepCount = 25;
inline constexpr std::array<double, kFineStepCount> kFineStepUpperMm = {
    3,   6,   10,  14,  18,  24,  30,  40,  50,  65,  80,  100, 120,
    140, 160, 180, 200, 225, 250, 280, 315, 355, 400, 450, 500};

}  // namespace fitfeel::iso286::tables
