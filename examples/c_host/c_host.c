/* A C host that owns its 1 kHz servo loop, as a haptics SDK callback or an engine's fixed update
 * does: absolute deadlines on CLOCK_MONOTONIC, one fitfeel_step per period. The "device" is the
 * paper's robot: from 1 mm before the entrance along +y at 10 mm/s.
 * Usage: fitfeel_example_c_host SCENARIO TICKS */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "framework/capi/fitfeel.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s SCENARIO TICKS\n", argv[0]);
    return 2;
  }
  const long ticks = atol(argv[2]);
  fitfeel_scene* scene = NULL;
  const int status = fitfeel_open_file(argv[1], 0, &scene);
  if (status != FITFEEL_OK) {
    fprintf(stderr, "%s\n", fitfeel_thread_last_error());
    return status == FITFEEL_SCENARIO_ERROR ? 2 : 1;
  }
  struct timespec next;
  clock_gettime(CLOCK_MONOTONIC, &next);
  double peak = 0.0;
  long k = 0;
  for (; k < ticks; ++k) {
    fitfeel_device_state d;
    memset(&d, 0, sizeof d);
    d.time = k / 1000.0;
    d.position[1] = -1e-3 + 0.01 * d.time;
    d.orientation[0] = 1.0;
    d.velocity[1] = 0.01;
    fitfeel_wrench w;
    if (fitfeel_step(scene, &d, &w) != FITFEEL_OK) break;
    if (-w.force[1] > peak) peak = -w.force[1];
    next.tv_nsec += 1000000;
    if (next.tv_nsec >= 1000000000) {
      next.tv_nsec -= 1000000000;
      ++next.tv_sec;
    }
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
  }
  fitfeel_contact c;
  fitfeel_contact_state(scene, &c);
  printf("%ld ticks at 1 kHz, depth %.3f mm, stage %s, peak axial resistance %.3g N\n", k,
         c.depth * 1e3, c.stage ? "constrained" : "positioning", peak);
  fitfeel_close(scene);
  return 0;
}
