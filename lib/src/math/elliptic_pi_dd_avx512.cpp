// The double-double Pi kernel (elliptic_pi_dd_kernel.inc) for x86-64 CPUs with AVX2, FMA and
// AVX-512VL (its vectors stay 256 bits wide; AVX-512 adds the reciprocal estimate vrcp14pd and
// 32 vector registers).
#include "elliptic_pi_dd_entry.h"

#if DISKLAB_PI_DD
#define DL_KERNEL_NS pi_avx512
#define DL_ISA "avx2,fma,avx512f,avx512vl"
#define DL_RCP14 1
#include "elliptic_pi_dd_kernel.inc"
#endif
