/* The core, for the translation unit of an FMU (see core/core.h). */
#include "core/instance.c"
#include "core/log.c"
#include "core/modes.c"
#include "core/clock.c"
#include "core/values.c"
#include "core/strings.c"
#include "core/state.c"
