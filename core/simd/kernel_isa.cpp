#include "simd/kernel_isa.hpp"

namespace creepwork {

bool kernel_isa_supported(KernelIsa isa)
{
#if CREEPWORK_X86_KERNELS
    // Idempotent; needed when called before static constructors have run
    // (a solver made by another library's or program's constructor).
    __builtin_cpu_init();
#endif
    switch (isa) {
    case KernelIsa::baseline: return true;
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx2: return __builtin_cpu_supports("avx2");
    case KernelIsa::avx512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
               __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
#else
    case KernelIsa::avx2:
    case KernelIsa::avx512: return false;
#endif
    }
    return false;
}

KernelIsa best_kernel_isa()
{
    if (kernel_isa_supported(KernelIsa::avx512)) return KernelIsa::avx512;
    if (kernel_isa_supported(KernelIsa::avx2)) return KernelIsa::avx2;
    return KernelIsa::baseline;
}

const char* kernel_isa_name(KernelIsa isa)
{
    switch (isa) {
    case KernelIsa::baseline: return "baseline";
    case KernelIsa::avx2: return "avx2";
    case KernelIsa::avx512: return "avx512";
    }
    return "unknown";
}

} // namespace creepwork
