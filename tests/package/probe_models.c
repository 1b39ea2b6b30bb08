/* Loads a liboctocap by path (as an engine's plugin loader does) and creates a detector for a shipped model by name:
 * prints "ok" or the library's error, which names the path it looked in. check_unity_package.py runs it on the
 * packaged library to see that the models beside it are the ones it finds. */
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include <octocap/octocap.h>

typedef octocap_result_t (*defaults_fn)(octocap_detector_config_t*, uint32_t);
typedef octocap_result_t (*create_fn)(const octocap_detector_config_t*, octocap_detector_t**);
typedef void (*destroy_fn)(octocap_detector_t*);
typedef const char* (*error_fn)(void);

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s LIBOCTOCAP MODEL_NAME\n", argv[0]);
    return 2;
  }
  void* lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    printf("dlopen: %s\n", dlerror());
    return 1;
  }
  /* POSIX's form for a function from dlsym (ISO C has no object-to-function pointer conversion). */
  defaults_fn defaults;
  create_fn create;
  destroy_fn destroy;
  error_fn last_error;
  *(void**)(&defaults) = dlsym(lib, "octocap_detector_config_defaults");
  *(void**)(&create) = dlsym(lib, "octocap_detector_create");
  *(void**)(&destroy) = dlsym(lib, "octocap_detector_destroy");
  *(void**)(&last_error) = dlsym(lib, "octocap_last_error");
  if (!defaults || !create || !destroy || !last_error) {
    printf("missing symbols\n");
    return 1;
  }
  octocap_detector_config_t cfg;
  defaults(&cfg, (uint32_t)sizeof cfg);
  strncpy(cfg.model, argv[2], sizeof cfg.model - 1);
  octocap_detector_t* detector = NULL;
  if (create(&cfg, &detector) != OCTOCAP_OK) {
    printf("error: %s\n", last_error());
    return 1;
  }
  destroy(detector);
  printf("ok\n");
  return 0;
}
