#include "framework/stability/stability_map.h"
#include <gtest/gtest.h>
