#include "framework/core/demand.h"

#include <cstdio>
#include <cstdlib>

namespace fitfeel::internal {

void DemandFailed(const char* condition, const char* file, int line) noexcept {
  // fprintf, not iostreams: the stream objects may already be gone when a static's destructor
  // trips a demand, and nothing here may allocate through a broken heap.
  std::fprintf(stderr, "%s:%d: demand failed: %s\n", file, line, condition);
  std::fflush(stderr);
  std::abort();
}

}  // namespace fitfeel::internal
