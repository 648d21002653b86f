#pragma once

// The framework library is built with hidden visibility; its interfaces, exception types and entry
// points are marked with FITFEEL_API so plugins and executables can link against them and so
// dynamic_cast and catch work across library boundaries.
#define FITFEEL_API __attribute__((visibility("default")))
