// The instruction sets the core's SIMD kernels are compiled for (the march's,
// the semi-Hertzian method's, the FFT's), and the one way a kernel gets its
// per-ISA entry points and their dispatch.
//
// A kernel is written once, as a struct with a static member template
// run<W>(args...) that works on W doubles per vector (simd.hpp) and is
// always inlined. run_kernel<Kernel>(isa, args...) calls the copy of it
// compiled for isa: the build's baseline (SSE2 on x86-64, W = 2) and, on
// x86-64 with GCC or Clang, AVX2 (W = 4) and AVX-512 (W = 8). A solver picks
// the widest ISA the CPU runs once, when it is made. Every copy gives
// bitwise the same results (march/march.hpp says why), which test_core_kernels
// checks, so no copy is kept equal by hand.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CREEPWORK_X86_KERNELS 1
#define CREEPWORK_TARGET_AVX2 __attribute__((target("avx2")))
#define CREEPWORK_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))
#else
#define CREEPWORK_X86_KERNELS 0
#endif

namespace creepwork {

enum class KernelIsa {
    baseline, // the build's own target (SSE2 on x86-64)
    avx2,
    avx512,   // AVX-512 F, VL, DQ, BW
};

// The widest kernel this CPU (and OS) runs.
KernelIsa best_kernel_isa();
bool kernel_isa_supported(KernelIsa isa);
const char* kernel_isa_name(KernelIsa isa); // "baseline", "avx2", "avx512"

// The vector width W each ISA's copy of a kernel is compiled for. A kernel
// derives from it, and narrows a width by redeclaring it (the field export
// gains nothing from eight lanes).
struct KernelWidths {
    static constexpr int baseline = 2, avx2 = 4, avx512 = 8;
};

namespace kernel_entry {

// One entry point per ISA: Kernel::run<W> inlined and compiled for it. The
// baseline's is not inlined into the dispatch, so that each ISA's copy is a
// function of its own (the profile shows which one ran).
template <class Kernel, class... Args>
__attribute__((noinline)) void baseline(const Args&... args)
{
    Kernel::template run<Kernel::baseline>(args...);
}
#if CREEPWORK_X86_KERNELS
template <class Kernel, class... Args>
CREEPWORK_TARGET_AVX2 void avx2(const Args&... args)
{
    Kernel::template run<Kernel::avx2>(args...);
}
template <class Kernel, class... Args>
CREEPWORK_TARGET_AVX512 void avx512(const Args&... args)
{
    Kernel::template run<Kernel::avx512>(args...);
}
#endif

} // namespace kernel_entry

// Kernel::run<W>(args...) in isa's copy (isa must be supported).
template <class Kernel, class... Args>
inline void run_kernel(KernelIsa isa, const Args&... args)
{
    switch (isa) {
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx512: kernel_entry::avx512<Kernel>(args...); return;
    case KernelIsa::avx2: kernel_entry::avx2<Kernel>(args...); return;
#endif
    default: kernel_entry::baseline<Kernel>(args...); return;
    }
}

} // namespace creepwork
