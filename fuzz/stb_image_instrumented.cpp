// stb_image compiled into the weather_png harness, so the fuzzer sees coverage inside the decoder
// and ASan checks its memory accesses: the tool links Debian's prebuilt libstb, which is neither
// instrumented nor sanitized. Same source (the libstb-dev header); the executable's definitions
// take precedence over the shared library's.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
