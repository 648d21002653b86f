/* fitfeel's C interface (C99): for hosts that own their servo loop, a haptics SDK's callback or a
 * game engine's fixed update, and for foreign runtimes (C#'s DllImport, Python's ctypes).
 *
 * Opaque handles, integer status codes, and a last-error text per handle and per thread; no C++
 * type or exception crosses it. docs/embedding.md says which call may run on which thread.
 *
 *   fitfeel_scene* s;
 *   if (fitfeel_open_file("scenarios/paper-case1-h7js6.yaml", 0, &s) != FITFEEL_OK) {
 *     fputs(fitfeel_thread_last_error(), stderr);
 *   }
 *   fitfeel_device_state d = {0};  d.orientation[0] = 1.0;  // w, x, y, z
 *   fitfeel_wrench w;
 *   while (fitfeel_step(s, &d, &w) == FITFEEL_OK) { ... apply w, read the device into d ... }
 *   fitfeel_close(s);
 */
#ifndef FITFEEL_CAPI_FITFEEL_H_
#define FITFEEL_CAPI_FITFEEL_H_

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FITFEEL_C_API __attribute__((visibility("default")))
#define FITFEEL_C_ABI_VERSION 2

enum {
  FITFEEL_OK = 0,
  FITFEEL_DONE = 1,            /* every tick of the scene's run.duration is done */
  FITFEEL_INVALID_ARGUMENT = -1, /* a null pointer or a handle in the wrong state */
  FITFEEL_SCENARIO_ERROR = -2, /* the scenario was refused: file:line:column, key, expected, found */
  FITFEEL_ERROR = -3           /* anything else the framework refused (the text says what) */
};

typedef struct fitfeel_scene fitfeel_scene;

/* The device's state at a tick, in the scene's frame (right-handed, y along the mating axis, 0 at
 * the fixed part's entrance), SI units (s, m, m/s, rad/s). Only the device's: the radial load on
 * the part is the scene's part_motion.radial_load, applied by the same code as in `fitfeel run`. */
typedef struct {
  double time;               /* s since the start of the run */
  double position[3];        /* the moving part's leading end */
  double orientation[4];     /* unit quaternion w, x, y, z */
  double velocity[3];
  double angular_velocity[3];
  uint32_t buttons;
} fitfeel_device_state;

typedef struct {
  double force[3];   /* N, to apply to the device */
  double torque[3];  /* N*m */
} fitfeel_wrench;

/* The contact at the last step. */
typedef struct {
  int stage;                    /* 0 positioning (free motion), 1 constrained */
  int engaged;                  /* the surfaces overlap along the axis */
  int interference;             /* some cell interferes */
  double depth;                 /* m, insertion depth */
  double max_interference;      /* m */
  double interference_volume;   /* m^3 */
  double model_force[3];        /* N, the model's force before the device's safety chain */
} fitfeel_contact;

FITFEEL_C_API int fitfeel_abi_version(void);

/* Loads and checks a scene (plugins from FITFEEL_PLUGIN_PATH and the installed ones), prepares
 * it (skin model shapes, tables) and makes it ready to step. seed 0 keeps the scene's run.seed.
 * Allocates; may take a fraction of a second. On failure *out is null and the thread's last
 * error says why. */
FITFEEL_C_API int fitfeel_open_file(const char* path, uint64_t seed, fitfeel_scene** out);
/* The same from YAML text; `name` is what error messages call the text (e.g. "engine.yaml"). */
FITFEEL_C_API int fitfeel_open_yaml(const char* yaml, const char* name, uint64_t seed,
                                    fitfeel_scene** out);

/* One tick: the device state in, the wrench to render out. Never allocates, locks, blocks or
 * throws. FITFEEL_DONE (and a zero wrench) once run.duration's ticks are done. Call it from one
 * thread at a time per handle (the servo thread). */
FITFEEL_C_API int fitfeel_step(fitfeel_scene* scene, const fitfeel_device_state* device,
                               fitfeel_wrench* out);
/* The contact at the last step; cheap, no allocation. Same thread as fitfeel_step. */
FITFEEL_C_API int fitfeel_contact_state(const fitfeel_scene* scene, fitfeel_contact* out);
/* Ticks done so far. */
FITFEEL_C_API uint64_t fitfeel_ticks(const fitfeel_scene* scene);

/* The contact pressure on each cell of the inner part's grid at the last step's pose, Pa,
 * row-major (rows along the mating axis, columns around or across it), the cells' interference
 * times the law's pressure per unit interference (what `fitfeel plot pressure` draws). With
 * `pressure` null or `capacity` (doubles) too small, only *rows and *columns are set and
 * FITFEEL_INVALID_ARGUMENT returned: ask first, then allocate. FITFEEL_ERROR for a law without a
 * pressure field (the handle's last error says so). Allocates: never from the servo callback;
 * between steps, on the stepping thread. */
FITFEEL_C_API int fitfeel_pressure_map(fitfeel_scene* scene, double* pressure, int capacity,
                                       int* rows, int* columns);

/* Writes DIR/trace.csv and DIR/summary.json of the ticks stepped so far, as `fitfeel run` writes
 * them (both or neither; DIR created if needed). Allocates and does I/O: never from the servo
 * callback; between steps or after the last, on the stepping thread. */
FITFEEL_C_API int fitfeel_write_outputs(fitfeel_scene* scene, const char* dir);

/* The last error on this handle (pressure map, outputs), or on this thread for calls without a
 * handle (open); "" if none. Valid until the next call on the handle / thread. */
FITFEEL_C_API const char* fitfeel_last_error(const fitfeel_scene* scene);
FITFEEL_C_API const char* fitfeel_thread_last_error(void);

/* Frees the handle; null is allowed. Not while another thread steps it. */
FITFEEL_C_API void fitfeel_close(fitfeel_scene* scene);

#ifdef __cplusplus
}
#endif

#endif /* FITFEEL_CAPI_FITFEEL_H_ */
