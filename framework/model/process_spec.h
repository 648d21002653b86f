#pragma once

namespace fitfeel {

// How the manufacturing process spreads a part's size and form (the scenario's per-part
// `process:`; docs/process-models.md).
//  - paper: the reference paper's draws, uniform over the tolerance (a worst-case population).
//  - statistical: a capable process. Size is normal with the capability indices Cp and Cpk
//    (ISO 22514-2): sigma = (U - L) / (6 Cp) and the mean 3 sigma Cpk inside the limit it leans
//    toward. A form deviation is a zone width: non-negative and skewed, with its natural bound at
//    zero; it follows a Rayleigh law (the length of a two-dimensional normal error, the usual
//    model of roundness, straightness and position), whose one-sided capability
//    Cpk = (t - mean) / (3 sd) sets its scale. A part that leaves its tolerance is scrap: it is
//    rejected and drawn again, and the rejections are counted.
enum class ProcessKind { kPaper, kStatistical };

// Which size limit the mean of a process with Cpk < Cp sits closer to. Machinists work toward
// the maximum material limit (a shaft's upper, a bore's lower), where a part can still be
// reworked, so that is the default.
enum class ProcessLean { kMaximumMaterial, kLeastMaterial };

struct ProcessSpec {
  ProcessKind kind = ProcessKind::kPaper;
  double cp = 4.0 / 3.0;   // size capability; 1.33 is the usual requirement of a capable process
  double cpk = 4.0 / 3.0;  // <= cp
  double form_cpk = 4.0 / 3.0;  // one-sided capability of each form characteristic
  ProcessLean lean = ProcessLean::kMaximumMaterial;
};

}  // namespace fitfeel
