/* The C side of the C# binding's test: steps a scene through the C interface with the device
 * states of a recording (`fitfeel run` with outputs: [recording]) and prints every tick's wrench
 * as the bits of its doubles, the form the C# console host (examples/csharp_host) prints, so
 * that the two outputs compare with diff. Fails when a wrench differs from the one the recording
 * says the run commanded: the C# host is thereby compared with `fitfeel run` too.
 * Usage: fitfeel_capi_replay_host SCENARIO RECORDING */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "framework/capi/fitfeel.h"

enum { kColumns = 64 };

/* The recording's header names its columns; a state's fields are looked up by name so that a
 * column added to the format does not shift them. */
static int column(char names[][64], int count, const char* name) {
  for (int i = 0; i < count; ++i) {
    if (strcmp(names[i], name) == 0) return i;
  }
  fprintf(stderr, "recording: no column %s\n", name);
  exit(1);
}

static uint64_t bits(double v) {
  uint64_t b;
  memcpy(&b, &v, sizeof b);
  return b;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s SCENARIO RECORDING\n", argv[0]);
    return 2;
  }
  FILE* in = fopen(argv[2], "r");
  if (in == NULL) {
    perror(argv[2]);
    return 1;
  }
  fitfeel_scene* scene = NULL;
  if (fitfeel_open_file(argv[1], 0, &scene) != FITFEEL_OK) {
    fprintf(stderr, "%s\n", fitfeel_thread_last_error());
    return 1;
  }
  static char line[8192];
  static char names[kColumns][64];
  int count = 0;
  int at[20];
  static const char* const wanted[20] = {
      "t_s",      "x_m",      "y_m",      "z_m",        "qw_1",       "qx_1",      "qy_1",
      "qz_1",     "vx_m/s",   "vy_m/s",   "vz_m/s",     "wx_rad/s",   "wy_rad/s",  "wz_rad/s",
      "fx_cmd_N", "fy_cmd_N", "fz_cmd_N", "tx_cmd_N*m", "ty_cmd_N*m", "tz_cmd_N*m"};
  int buttons = -1;
  long tick = 0, differing = 0;
  double peak = 0.0;
  while (fgets(line, sizeof line, in) != NULL) {
    if (line[0] == '#') continue;
    char* field[kColumns];
    int n = 0;
    for (char* s = strtok(line, " \t\r\n"); s != NULL && n < kColumns;
         s = strtok(NULL, " \t\r\n")) {
      field[n++] = s;
    }
    if (count == 0) {
      for (int i = 0; i < n; ++i) snprintf(names[i], sizeof names[i], "%s", field[i]);
      count = n;
      for (int i = 0; i < 20; ++i) at[i] = column(names, count, wanted[i]);
      buttons = column(names, count, "buttons_bits");
      continue;
    }
    if (n != count) {
      fprintf(stderr, "recording: %d fields on a row of %d columns\n", n, count);
      return 1;
    }
    double v[20];
    for (int i = 0; i < 20; ++i) v[i] = strtod(field[at[i]], NULL);
    fitfeel_device_state d;
    d.time = v[0];
    for (int k = 0; k < 3; ++k) {
      d.position[k] = v[1 + k];
      d.velocity[k] = v[8 + k];
      d.angular_velocity[k] = v[11 + k];
    }
    for (int k = 0; k < 4; ++k) d.orientation[k] = v[4 + k];
    d.buttons = (uint32_t)strtoul(field[buttons], NULL, 10);
    fitfeel_wrench w;
    if (fitfeel_step(scene, &d, &w) != FITFEEL_OK) {
      fprintf(stderr, "tick %ld: the scene ended before the recording\n", tick);
      return 1;
    }
    const double got[6] = {w.force[0],  w.force[1],  w.force[2],
                           w.torque[0], w.torque[1], w.torque[2]};
    printf("%ld", tick);
    for (int k = 0; k < 6; ++k) {
      printf(" %016" PRIx64, bits(got[k]));
      if (bits(got[k]) != bits(v[14 + k]) && differing++ < 5) {
        fprintf(stderr, "tick %ld: wrench component %d %.17g, fitfeel run commanded %.17g\n", tick,
                k, got[k], v[14 + k]);
      }
    }
    printf("\n");
    if (fabs(got[1]) > peak) peak = fabs(got[1]);
    ++tick;
  }
  fclose(in);
  printf("%ld ticks, peak axial resistance %.3f N\n", tick, peak);
  fitfeel_close(scene);
  if (differing > 0)
    fprintf(stderr, "%ld wrench components differ from fitfeel run's\n", differing);
  return differing > 0 || tick == 0 ? 1 : 0;
}
