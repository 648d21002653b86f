// The C interface from C++: stepping never allocates, refusals come back as status codes with the
// CLI's located messages, and a handle steps to FITFEEL_DONE.
#include <cstring>
#include <string>

#include "framework/capi/fitfeel.h"
#include "framework/testing/allocation_counter.h"
// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace {

// The paper's robot: from 1 mm before the entrance along +y at 10 mm/s, carrying no load.
fitfeel_device_state Robot(int k) {
  fitfeel_device_state d;
  std::memset(&d, 0, sizeof(d));
  d.time = k / 1000.0;
  d.position[1] = -1e-3 + 0.01 * d.time;
  d.orientation[0] = 1.0;
  d.velocity[1] = 0.01;
  return d;
}

TEST(CApi, StepNeverAllocates) {
  // Before the handle opens: a skipped test must not leave it unclosed (LeakSanitizer).
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  fitfeel_scene* scene = nullptr;
  ASSERT_EQ(fitfeel_open_file("scenarios/paper-case1-h7js6.yaml", 0, &scene), FITFEEL_OK)
      << fitfeel_thread_last_error();
  fitfeel_wrench w;
  fitfeel_contact c;
  double largest = 0.0;
  int constrained = 0;
  fitfeel::test_support::ScopedAllocationCounter allocations;
  for (int k = 0; k < 3000; ++k) {
    const fitfeel_device_state d = Robot(k);
    ASSERT_EQ(fitfeel_step(scene, &d, &w), FITFEEL_OK);
    ASSERT_EQ(fitfeel_contact_state(scene, &c), FITFEEL_OK);
    largest = std::max(largest, std::abs(w.force[1]));
    constrained += c.stage;
  }
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_EQ(fitfeel_ticks(scene), 3000u);
  EXPECT_GT(constrained, 2000) << "the robot's 30 mm should carry the shaft into the bushing";
  EXPECT_GT(largest, 0.0) << "the fit renders some axial resistance";
  fitfeel_close(scene);
}

TEST(CApi, StepsToDoneAfterTheScenesDuration) {
  fitfeel_scene* scene = nullptr;
  ASSERT_EQ(fitfeel_open_file("scenarios/paper-case1-h7js6.yaml", 3, &scene), FITFEEL_OK);
  fitfeel_wrench w;
  int k = 0;
  for (; k < 100000; ++k) {
    const fitfeel_device_state d = Robot(k);
    if (fitfeel_step(scene, &d, &w) != FITFEEL_OK) break;
  }
  EXPECT_EQ(k, 4000) << "run.duration 4 s at 1 kHz";
  const fitfeel_device_state d = Robot(k);
  EXPECT_EQ(fitfeel_step(scene, &d, &w), FITFEEL_DONE);
  EXPECT_EQ(w.force[1], 0.0);
  fitfeel_close(scene);
}

TEST(CApi, RefusalsAreStatusCodesWithLocatedMessages) {
  fitfeel_scene* scene = reinterpret_cast<fitfeel_scene*>(1);
  EXPECT_EQ(fitfeel_open_file("no/such/scene.yaml", 0, &scene), FITFEEL_SCENARIO_ERROR);
  EXPECT_EQ(scene, nullptr);
  EXPECT_NE(std::string(fitfeel_thread_last_error()).find("no/such/scene.yaml"),
            std::string::npos);
  EXPECT_EQ(fitfeel_open_yaml("scenario: x\nsurface: [", "engine.yaml", 0, &scene),
            FITFEEL_SCENARIO_ERROR);
  EXPECT_NE(std::string(fitfeel_thread_last_error()).find("engine.yaml:"), std::string::npos)
      << fitfeel_thread_last_error();
  EXPECT_EQ(fitfeel_open_file(nullptr, 0, &scene), FITFEEL_INVALID_ARGUMENT);
  EXPECT_EQ(fitfeel_step(nullptr, nullptr, nullptr), FITFEEL_INVALID_ARGUMENT);
  fitfeel_close(nullptr);
}

}  // namespace
