/* Counting allocator for the no-allocation tests: the test executable
 * defines malloc and friends itself (the dynamic linker binds every
 * library's calls, libstdc++'s operator new included, to the executable's
 * definitions first) and forwards to glibc's __libc_* entry points.
 * Include in exactly one translation unit of a test that is built without
 * sanitizers (their runtimes own malloc). */
#ifndef CREEPWORK_COUNT_MALLOC_H
#define CREEPWORK_COUNT_MALLOC_H

#include <errno.h>
#include <malloc.h>
#include <stddef.h>
#include <stdlib.h>

/* glibc declares these noexcept in C++; a definition must agree. */
#ifdef __cplusplus
#define CW_ALLOC_NOEXCEPT noexcept
#else
#define CW_ALLOC_NOEXCEPT
#endif

#ifdef __cplusplus
extern "C" {
#endif

void* __libc_malloc(size_t size);
void* __libc_calloc(size_t count, size_t size);
void* __libc_realloc(void* p, size_t size);
void* __libc_memalign(size_t alignment, size_t size);
void __libc_free(void* p);

static int cw_counting_enabled;
static long cw_allocations;

static void cw_count(void)
{
    if (__atomic_load_n(&cw_counting_enabled, __ATOMIC_RELAXED))
        __atomic_fetch_add(&cw_allocations, 1, __ATOMIC_RELAXED);
}

/* Starts counting from zero. */
static inline void cw_count_start(void)
{
    __atomic_store_n(&cw_allocations, 0, __ATOMIC_SEQ_CST);
    __atomic_store_n(&cw_counting_enabled, 1, __ATOMIC_SEQ_CST);
}

/* Stops counting; returns the allocations since cw_count_start. */
static inline long cw_count_stop(void)
{
    __atomic_store_n(&cw_counting_enabled, 0, __ATOMIC_SEQ_CST);
    return __atomic_load_n(&cw_allocations, __ATOMIC_SEQ_CST);
}

void* malloc(size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    return __libc_malloc(size);
}

void* calloc(size_t count, size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    return __libc_calloc(count, size);
}

void* realloc(void* p, size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    return __libc_realloc(p, size);
}

void* memalign(size_t alignment, size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    return __libc_memalign(alignment, size);
}

void* aligned_alloc(size_t alignment, size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    return __libc_memalign(alignment, size);
}

int posix_memalign(void** out, size_t alignment, size_t size) CW_ALLOC_NOEXCEPT
{
    cw_count();
    void* p = __libc_memalign(alignment, size);
    if (!p) return ENOMEM;
    *out = p;
    return 0;
}

void free(void* p) CW_ALLOC_NOEXCEPT { __libc_free(p); }

#ifdef __cplusplus
}
#endif

#endif
