/* The legacy layer's per-thread state on plain pthreads (no OpenMP), as a
 * C host calls the F77 routines (gfortran's convention: every argument by
 * reference, a CHARACTER's length appended as size_t). Checks:
 *   - CWLAST: four threads fail CWKALK at the same time with their own
 *     nu (out of [0, 0.5], Kalker's table) and, after a barrier that lets
 *     every other thread fail too, each reads its own nu; after a success
 *     its own message is blank.
 */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "creepwork/creepwork.h"

/* The legacy routines (creepwork_legacy.inc), as gfortran names them. */
void cwkalk_(const double* aob, const double* pnu, double* c11, double* c22, double* c23,
             double* c33, int* ierr);
void cwlast_(char* msg, size_t len);

enum { kThreads = 4, kRounds = 40 };

static pthread_barrier_t barrier;
static int failures[kThreads];

static void* worker(void* arg)
{
    const int t = (int)(size_t)arg;
    /* Thread t's own invalid Poisson's ratio and how CWLAST prints it. */
    const double bad_nu[kThreads] = {0.75, 1.5, 2.5, 3.5};
    const char* printed[kThreads] = {"nu = 0.75", "nu = 1.5", "nu = 2.5", "nu = 3.5"};
    const double aob = 1.0, good_nu = 0.25;
    char msg[200];
    for (int round = 0; round < kRounds; ++round) {
        double c11, c22, c23, c33;
        int ierr = 0;
        cwkalk_(&aob, &bad_nu[t], &c11, &c22, &c23, &c33, &ierr);
        if (ierr != CW_ERR_INVALID_INPUT) failures[t]++;
        pthread_barrier_wait(&barrier); /* every thread has failed now */
        cwlast_(msg, sizeof msg);
        msg[sizeof msg - 1] = '\0';
        if (!strstr(msg, printed[t])) {
            if (failures[t]++ < 3) fprintf(stderr, "thread %d read: %.80s\n", t, msg);
        }
        for (int u = 0; u < kThreads; ++u)
            if (u != t && strstr(msg, printed[u])) failures[t]++;
        pthread_barrier_wait(&barrier);
        cwkalk_(&aob, &good_nu, &c11, &c22, &c23, &c33, &ierr);
        cwlast_(msg, sizeof msg);
        for (size_t i = 0; i < sizeof msg; ++i)
            if (msg[i] != ' ') {
                failures[t]++;
                break;
            }
    }
    return NULL;
}

int main(void)
{
    int bad = 0;
    pthread_t threads[kThreads];
    pthread_barrier_init(&barrier, NULL, kThreads);
    for (int t = 0; t < kThreads; ++t)
        pthread_create(&threads[t], NULL, worker, (void*)(size_t)t);
    for (int t = 0; t < kThreads; ++t) pthread_join(threads[t], NULL);
    pthread_barrier_destroy(&barrier);
    for (int t = 0; t < kThreads; ++t) bad += failures[t];

    if (bad) {
        printf("%d checks failed\n", bad);
        return 1;
    }
    printf("all checks passed: %d threads x %d rounds\n", kThreads, kRounds);
    return 0;
}
