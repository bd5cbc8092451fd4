/* The entry point of fuzz_<Block>: bit 6 of the input's second byte picks the FMU's FMI 3.0
 * build, else FMI 2.0. fuzz_fmu.c is compiled once with each version's translation unit of the
 * block (units/fmi2/<Block>.c, units/fmi3/<Block>.c), as lgf_fuzz_fmi2 and lgf_fuzz_fmi3; the
 * two units share no symbol (every one but the fmi2/fmi3 entry points is static). */
#include <stddef.h>
#include <stdint.h>

int lgf_fuzz_fmi2(const uint8_t *data, size_t size);
int lgf_fuzz_fmi3(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return size > 1 && (data[1] & 0x40) ? lgf_fuzz_fmi3(data, size) : lgf_fuzz_fmi2(data, size);
}
