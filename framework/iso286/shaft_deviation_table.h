#pragma once

// Fundamental deviations of shafts, ISO 286-1 Table 2 (ISO 286-1:1988 Table 2; the same values are
// in ISO 286-1:2010), for nominal sizes up to 500 mm, in micrometres. One row per intermediate size
// step (kFineStepUpperMm); where the standard gives one value for a whole main step (merged cells)
// it is repeated on each of the step's rows. kBlank marks a cell the standard leaves empty: that
// letter is not defined at that size.
//
// Footnotes carried by the lookup, not by the cells: a and b are not used for nominal sizes up to
// and including 1 mm; js is +-IT/2 (no column here); the k column holds the value for grades IT4 to
// IT7 (k is 0 for IT3 and finer and for IT8 and coarser); j has one column for IT5 and IT6, one for
// IT7 and one for IT8 and is not defined for other grades.

#include <array>
#include <limits>

#include "framework/iso286/size_steps_table.h"

namespace fitfeel::iso286::tables {

inline constexpr double kBlank = std::numeric_limits<double>::quiet_NaN();

// Upper deviations es of the shafts a to h (the fundamental deviation is the upper one).
enum ShaftUpperColumn { kA, kB, kC, kCD, kD, kE, kEF, kF, kFG, kG, kH, kShaftUpperColumnCount };

// clang-format off
inline constexpr std::array<std::array<double, kShaftUpperColumnCount>, kFineStepCount>
    kShaftUpperDeviationUm = {{
  //       a        b        c       cd        d        e       ef        f       fg        g        h
  {{   -270,    -140,     -60,     -34,     -20,     -14,     -10,      -6,      -4,      -2,       0}},  // 0-3
  {{   -270,    -140,     -70,     -46,     -30,     -20,     -14,     -10,      -6,      -4,       0}},  // 3-6
  {{   -280,    -150,     -80,     -56,     -40,     -25,     -18,     -13,      -8,      -5,       0}},  // 6-10
  {{   -290,    -150,     -95,  kBlank,     -50,     -32,  kBlank,     -16,  kBlank,      -6,       0}},  // 10-14
  {{   -290,    -150,     -95,  kBlank,     -50,     -32,  kBlank,     -16,  kBlank,      -6,       0}},  // 14-18
  {{   -300,    -160,    -110,  kBlank,     -65,     -40,  kBlank,     -20,  kBlank,      -7,       0}},  // 18-24
  {{   -300,    -160,    -110,  kBlank,     -65,     -40,  kBlank,     -20,  kBlank,      -7,       0}},  // 24-30
  {{   -310,    -170,    -120,  kBlank,     -80,     -50,  kBlank,     -25,  kBlank,      -9,       0}},  // 30-40
  {{   -320,    -180,    -130,  kBlank,     -80,     -50,  kBlank,     -25,  kBlank,      -9,       0}},  // 40-50
  {{   -340,    -190,    -140,  kBlank,    -100,     -60,  kBlank,     -30,  kBlank,     -10,       0}},  // 50-65
  {{   -360,    -200,    -150,  kBlank,    -100,     -60,  kBlank,     -30,  kBlank,     -10,       0}},  // 65-80
  {{   -380,    -220,    -170,  kBlank,    -120,     -72,  kBlank,     -36,  kBlank,     -12,       0}},  // 80-100
  {{   -410,    -240,    -180,  kBlank,    -120,     -72,  kBlank,     -36,  kBlank,     -12,       0}},  // 100-120
  {{   -460,    -260,    -200,  kBlank,    -145,     -85,  kBlank,     -43,  kBlank,     -14,       0}},  // 120-140
  {{   -520,    -280,    -210,  kBlank,    -145,     -85,  kBlank,     -43,  kBlank,     -14,       0}},  // 140-160
  {{   -580,    -310,    -230,  kBlank,    -145,     -85,  kBlank,     -43,  kBlank,     -14,       0}},  // 160-180
  {{   -660,    -340,    -240,  kBlank,    -170,    -100,  kBlank,     -50,  kBlank,     -15,       0}},  // 180-200
  {{   -740,    -380,    -260,  kBlank,    -170,    -100,  kBlank,     -50,  kBlank,     -15,       0}},  // 200-225
  {{   -820,    -420,    -280,  kBlank,    -170,    -100,  kBlank,     -50,  kBlank,     -15,       0}},  // 225-250
  {{   -920,    -480,    -300,  kBlank,    -190,    -110,  kBlank,     -56,  kBlank,     -17,       0}},  // 250-280
  {{  -1050,    -540,    -330,  kBlank,    -190,    -110,  kBlank,     -56,  kBlank,     -17,       0}},  // 280-315
  {{  -1200,    -600,    -360,  kBlank,    -210,    -125,  kBlank,     -62,  kBlank,     -18,       0}},  // 315-355
  {{  -1350,    -680,    -400,  kBlank,    -210,    -125,  kBlank,     -62,  kBlank,     -18,       0}},  // 355-400
  {{  -1500,    -760,    -440,  kBlank,    -230,    -135,  kBlank,     -68,  kBlank,     -20,       0}},  // 400-450
  {{  -1650,    -840,    -480,  kBlank,    -230,    -135,  kBlank,     -68,  kBlank,     -20,       0}},  // 450-500
}};
// clang-format on

// Lower deviations ei of the shafts j to zc (the fundamental deviation is the lower one).
enum ShaftLowerColumn {
  kJ5J6,   // j for IT5 and IT6
  kJ7,     // j for IT7
  kJ8,     // j for IT8
  kK4To7,  // k for IT4 to IT7
  kM,
  kN,
  kP,
  kR,
  kS,
  kT,
  kU,
  kV,
  kX,
  kY,
  kZ,
  kZA,
  kZB,
  kZC,
  kShaftLowerColumnCount
};

// clang-format off
inline constexpr std::array<std::array<double, kShaftLowerColumnCount>, kFineStepCount>
    kShaftLowerDeviationUm = {{
  //   j5/6      j7      j8     k4-7     m       n       p       r       s       t       u       v       x       y       z      za      zb      zc
  {{    -2,     -4,     -6,      0,      2,      4,      6,     10,     14, kBlank,     18, kBlank,     20, kBlank,     26,     32,     40,     60}},  // 0-3
  {{    -2,     -4, kBlank,      1,      4,      8,     12,     15,     19, kBlank,     23, kBlank,     28, kBlank,     35,     42,     50,     80}},  // 3-6
  {{    -2,     -5, kBlank,      1,      6,     10,     15,     19,     23, kBlank,     28, kBlank,     34, kBlank,     42,     52,     67,     97}},  // 6-10
  {{    -3,     -6, kBlank,      1,      7,     12,     18,     23,     28, kBlank,     33, kBlank,     40, kBlank,     50,     64,     90,    130}},  // 10-14
  {{    -3,     -6, kBlank,      1,      7,     12,     18,     23,     28, kBlank,     33,     39,     45, kBlank,     60,     77,    108,    150}},  // 14-18
  {{    -4,     -8, kBlank,      2,      8,     15,     22,     28,     35, kBlank,     41,     47,     54,     63,     73,     98,    136,    188}},  // 18-24
  {{    -4,     -8, kBlank,      2,      8,     15,     22,     28,     35,     41,     48,     55,     64,     75,     88,    118,    160,    218}},  // 24-30
  {{    -5,    -10, kBlank,      2,      9,     17,     26,     34,     43,     48,     60,     68,     80,     94,    112,    148,    200,    274}},  // 30-40
  {{    -5,    -10, kBlank,      2,      9,     17,     26,     34,     43,     54,     70,     81,     97,    114,    136,    180,    242,    325}},  // 40-50
  {{    -7,    -12, kBlank,      2,     11,     20,     32,     41,     53,     66,     87,    102,    122,    144,    172,    226,    300,    405}},  // 50-65
  {{    -7,    -12, kBlank,      2,     11,     20,     32,     43,     59,     75,    102,    120,    146,    174,    210,    274,    360,    480}},  // 65-80
  {{    -9,    -15, kBlank,      3,     13,     23,     37,     51,     71,     91,    124,    146,    178,    214,    258,    335,    445,    585}},  // 80-100
  {{    -9,    -15, kBlank,      3,     13,     23,     37,     54,     79,    104,    144,    172,    210,    254,    310,    400,    525,    690}},  // 100-120
  {{   -11,    -18, kBlank,      3,     15,     27,     43,     63,     92,    122,    170,    202,    248,    300,    365,    470,    620,    800}},  // 120-140
  {{   -11,    -18, kBlank,      3,     15,     27,     43,     65,    100,    134,    190,    228,    280,    340,    415,    535,    700,    900}},  // 140-160
  {{   -11,    -18, kBlank,      3,     15,     27,     43,     68,    108,    146,    210,    252,    310,    380,    465,    600,    780,   1000}},  // 160-180
  {{   -13,    -21, kBlank,      4,     17,     31,     50,     77,    122,    166,    236,    284,    350,    425,    520,    670,    880,   1150}},  // 180-200
  {{   -13,    -21, kBlank,      4,     17,     31,     50,     80,    130,    180,    258,    310,    385,    470,    575,    740,    960,   1250}},  // 200-225
  {{   -13,    -21, kBlank,      4,     17,     31,     50,     84,    140,    196,    284,    340,    425,    520,    640,    820,   1050,   1350}},  // 225-250
  {{   -16,    -26, kBlank,      4,     20,     34,     56,     94,    158,    218,    315,    385,    475,    580,    710,    920,   1200,   1550}},  // 250-280
  {{   -16,    -26, kBlank,      4,     20,     34,     56,     98,    170,    240,    350,    425,    525,    650,    790,   1000,   1300,   1700}},  // 280-315
  {{   -18,    -28, kBlank,      4,     21,     37,     62,    108,    190,    268,    390,    475,    590,    730,    900,   1150,   1500,   1900}},  // 315-355
  {{   -18,    -28, kBlank,      4,     21,     37,     62,    114,    208,    294,    435,    530,    660,    820,   1000,   1300,   1650,   2100}},  // 355-400
  {{   -20,    -32, kBlank,      5,     23,     40,     68,    126,    232,    330,    490,    595,    740,    920,   1100,   1450,   1850,   2400}},  // 400-450
  {{   -20,    -32, kBlank,      5,     23,     40,     68,    132,    252,    360,    540,    660,    820,   1000,   1250,   1600,   2100,   2600}},  // 450-500
}};
// clang-format on

}  // namespace fitfeel::iso286::tables
