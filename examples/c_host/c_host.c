/* A C host that owns its 1 kHz servo loop, as a haptics SDK callback or an engine's fixed update
 * does: absolute deadlines on CLOCK_MONOTONIC, one fitfeel_step per period. The "device" is the
 * paper's robot: from 1 mm before the entrance along +y at 10 mm/s. The host passes only the
 * device's state: the part's radial load comes from the scene's part_motion, as in `fitfeel run`.
 * Prints the resistance over the constrained ticks as `fitfeel run`'s summary.json reports it
 * (17 digits, so that a test can compare them as doubles).
 * Usage: fitfeel_example_c_host SCENARIO [TICKS]   (no TICKS: the scene's whole run.duration) */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "framework/capi/fitfeel.h"

/* Mean, minimum and maximum, summed in tick order as summary.json's are. */
typedef struct {
  double sum, min, max;
  long count;
} stat;

static void stat_add(stat* s, double v) {
  s->sum += v;
  if (s->count == 0 || v < s->min) s->min = v;
  if (s->count == 0 || v > s->max) s->max = v;
  ++s->count;
}

static void stat_print(const char* name, const stat* s) {
  if (s->count == 0) {
    printf("%s none (no constrained tick)\n", name);
    return;
  }
  printf("%s mean %.17g N, min %.17g N, max %.17g N\n", name, s->sum / (double)s->count, s->min,
         s->max);
}

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    fprintf(stderr, "usage: %s SCENARIO [TICKS]\n", argv[0]);
    return 2;
  }
  const long ticks = argc == 3 ? atol(argv[2]) : -1;
  fitfeel_scene* scene = NULL;
  const int status = fitfeel_open_file(argv[1], 0, &scene);
  if (status != FITFEEL_OK) {
    fprintf(stderr, "%s\n", fitfeel_thread_last_error());
    return status == FITFEEL_SCENARIO_ERROR ? 2 : 1;
  }
  struct timespec next;
  clock_gettime(CLOCK_MONOTONIC, &next);
  stat axial = {0}, radial = {0};
  double peak = 0.0;
  long k = 0;
  fitfeel_contact c;
  for (; ticks < 0 || k < ticks; ++k) {
    fitfeel_device_state d;
    memset(&d, 0, sizeof d);
    d.time = k / 1000.0;
    d.position[1] = -1e-3 + 0.01 * d.time;
    d.orientation[0] = 1.0;
    d.velocity[1] = 0.01;
    fitfeel_wrench w;
    if (fitfeel_step(scene, &d, &w) != FITFEEL_OK) break;
    if (-w.force[1] > peak) peak = -w.force[1];
    /* The model's force before the device's safety chain, on constrained ticks: what
     * summary.json's axial_resistance_N and radial_resistance_N describe. */
    fitfeel_contact_state(scene, &c);
    if (c.stage == 1) {
      stat_add(&axial, fabs(c.model_force[1]));
      stat_add(&radial, hypot(c.model_force[0], c.model_force[2]));
    }
    next.tv_nsec += 1000000;
    if (next.tv_nsec >= 1000000000) {
      next.tv_nsec -= 1000000000;
      ++next.tv_sec;
    }
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
  }
  fitfeel_contact_state(scene, &c);
  printf("%ld ticks at 1 kHz, depth %.3f mm, stage %s, peak axial resistance %.3g N\n", k,
         c.depth * 1e3, c.stage ? "constrained" : "positioning", peak);
  printf("constrained ticks %ld\n", axial.count);
  stat_print("axial resistance ", &axial);
  stat_print("radial resistance", &radial);
  fitfeel_close(scene);
  return 0;
}
