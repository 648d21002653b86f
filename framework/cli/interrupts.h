#pragma once

#include <filesystem>

namespace fitfeel::cli {

// Removes from `folder` the temporaries of killed processes (RemoveStaleTemporaries: a SIGKILL
// leaves them) before a command writes there, and says so in one line on stderr:
//   fitfeel: note: removed 2 temporaries a killed run (process 4242) left in 'out/x':
//   .summary.json.tmp-4242, .trace.csv.tmp-4242
// (one line), and one line for each that could not be removed. Silent when there were none.
void SweepStaleTemporaries(const std::filesystem::path& folder);

}  // namespace fitfeel::cli
