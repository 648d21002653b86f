#include "framework/cli/interrupts.h"

#include <iostream>
#include <string>

#include "framework/core/temporary_files.h"

namespace fitfeel::cli {

void SweepStaleTemporaries(const std::filesystem::path& folder) {
  const StaleTemporaries stale = RemoveStaleTemporaries(folder);
  if (!stale.removed.empty()) {
    std::string processes;
    for (const long pid : stale.processes) {
      processes += (processes.empty() ? "" : ", ") + std::to_string(pid);
    }
    std::string names;
    for (const auto& file : stale.removed) {
      names += (names.empty() ? "" : ", ") + file.filename().string();
    }
    const std::size_t n = stale.removed.size();
    std::cerr << "fitfeel: note: removed " << n << (n == 1 ? " temporary" : " temporaries")
              << " a killed run (process" << (stale.processes.size() == 1 ? " " : "es ")
              << processes << ") left in '" << (folder.empty() ? "." : folder.string())
              << "': " << names << "\n";
  }
  for (const std::string& failure : stale.failures) {
    std::cerr << "fitfeel: note: could not remove a killed run's temporary " << failure << "\n";
  }
}

}  // namespace fitfeel::cli
