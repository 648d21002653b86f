// The global operator new of fitfeel_allocation_test, the one test binary that counts heap
// allocations (allocation_counter.h): every test that counts, and every surface plugin's
// conformance suite, is linked into it (cmake/FitfeelTargets.cmake, fitfeel_add_allocation_test).
#include "framework/testing/allocation_counter.h"

FITFEEL_COUNT_ALLOCATIONS();
