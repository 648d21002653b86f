#pragma once

// ISO 261 diameter-pitch combinations of M3 to M36 and the ISO 965-1 tables of fundamental
// deviations and grade-6 tolerances for them, in micrometres. The ISO 965-1 formulas do not
// reproduce every entry (the standard's tables keep some older values), so the tables are carried
// as data; the formulas are a cross-check in the tests, which list the entries that differ.

#include <array>

namespace fitfeel::iso965::tables {

// ISO 261 Table 1, first and second choice nominal diameters from 3 mm to 36 mm: the coarse pitch
// and the fine pitches, all in mm. M30 x 3 and M33 x 3 are in parentheses in ISO 261 (to be
// avoided where possible) and accepted here.
struct DiameterPitches {
  double nominal_mm;
  double coarse_mm;
  std::array<double, 4> fine_mm;  // largest first; 0 ends the list
};

// clang-format off
inline constexpr std::array<DiameterPitches, 18> kDiameterPitches = {{
  {3,   0.5,  {0.35}},
  {3.5, 0.6,  {0.35}},
  {4,   0.7,  {0.5}},
  {5,   0.8,  {0.5}},
  {6,   1,    {0.75}},
  {8,   1.25, {1, 0.75}},
  {10,  1.5,  {1.25, 1, 0.75}},
  {12,  1.75, {1.5, 1.25, 1}},
  {14,  2,    {1.5, 1.25, 1}},
  {16,  2,    {1.5, 1}},
  {18,  2.5,  {2, 1.5, 1}},
  {20,  2.5,  {2, 1.5, 1}},
  {22,  2.5,  {2, 1.5, 1}},
  {24,  3,    {2, 1.5, 1}},
  {27,  3,    {2, 1.5, 1}},
  {30,  3.5,  {3, 2, 1.5, 1}},
  {33,  3.5,  {3, 2, 1.5}},
  {36,  4,    {3, 2, 1.5}},
}};
// clang-format on

// ISO 965-1 Table 1, fundamental deviations per pitch: G (EI, internal), e, f and g (es, external;
// negative). H and h are zero. e is not defined below 0.5 mm (marked 0). e and f differ from the
// formulas -(50 + 11P) and -(30 + 11P) at several pitches; G and g equal 15 + 11P rounded.
struct PitchRow {
  double pitch_mm;
  double ei_g_um;
  double es_e_um;
  double es_f_um;
  double es_g_um;
  double td6_um;   // Td(6), major diameter of the external thread (Table 5)
  double td16_um;  // TD1(6), minor diameter of the internal thread (Table 4)
};

// clang-format off
inline constexpr std::array<PitchRow, 15> kPitchRows = {{
  //  P     G    e     f     g    Td(6) TD1(6)
  {0.35, 19,   0,  -34,  -19,   85,  100},
  {0.5,  20, -50,  -36,  -20,  106,  140},
  {0.6,  21, -53,  -36,  -21,  125,  160},
  {0.7,  22, -56,  -38,  -22,  140,  180},
  {0.75, 22, -56,  -38,  -22,  140,  190},
  {0.8,  24, -60,  -38,  -24,  150,  200},
  {1,    26, -60,  -40,  -26,  180,  236},
  {1.25, 28, -63,  -42,  -28,  212,  265},
  {1.5,  32, -67,  -45,  -32,  236,  300},
  {1.75, 34, -71,  -48,  -34,  265,  335},
  {2,    38, -71,  -52,  -38,  280,  375},
  {2.5,  42, -80,  -58,  -42,  335,  450},
  {3,    48, -85,  -63,  -48,  375,  500},
  {3.5,  53, -90,  -70,  -53,  425,  560},
  {4,    60, -95,  -75,  -60,  475,  600},
}};
// clang-format on

// ISO 965-1 diameter ranges of the pitch-diameter tolerances, mm: lower < d <= upper.
struct DiameterRange {
  double lower_mm;
  double upper_mm;
};
inline constexpr std::array<DiameterRange, 4> kRanges = {
    {{2.8, 5.6}, {5.6, 11.2}, {11.2, 22.4}, {22.4, 45}}};

// ISO 965-1 Table 6, Td2(6) per range and pitch, um. TD2(6) and the other grades follow from it
// (iso965.cc: GradeValue).
struct PitchTolerance {
  int range;  // index into kRanges
  double pitch_mm;
  double td26_um;
};

// clang-format off
inline constexpr std::array<PitchTolerance, 23> kTd2Grade6 = {{
  {0, 0.35,  67}, {0, 0.5,  75}, {0, 0.6,  85}, {0, 0.7,  90}, {0, 0.75, 90}, {0, 0.8,  95},
  {1, 0.75, 100}, {1, 1,   112}, {1, 1.25, 118}, {1, 1.5, 132},
  {2, 1,    118}, {2, 1.25, 132}, {2, 1.5, 140}, {2, 1.75, 150}, {2, 2,   160}, {2, 2.5, 170},
  {3, 1,    125}, {3, 1.5,  150}, {3, 2,   170}, {3, 3,   200}, {3, 3.5, 212}, {3, 4,   224},
  {3, 4.5,  236},
}};
// clang-format on

}  // namespace fitfeel::iso965::tables
