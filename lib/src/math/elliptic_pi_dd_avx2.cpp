// The double-double Pi kernel (elliptic_pi_dd_kernel.inc) for x86-64 CPUs with AVX2 and FMA.
#include "elliptic_pi_dd_entry.h"

#if DISKLAB_PI_DD
#define DL_KERNEL_NS pi_avx2
#define DL_ISA "avx2,fma"
#define DL_RCP14 0
#include "elliptic_pi_dd_kernel.inc"
#endif
