/* The FMI 2.0 layer, compiled into the one translation unit of an FMU: a binding includes
 * this file after it has defined `lgf_model` (see fmi2/model.h). */
#include "fmi2/lifecycle.c"
#include "fmi2/variables.c"
#include "fmi2/fmu_state.c"
