#include "rank_threads.hpp"

#include <algorithm>
#include <cstdlib>

#include <sched.h>
#include <unistd.h>

#include <creepwork/creepwork.h>

namespace cwcampaign {

int default_threads(int ranks_on_node)
{
    int threads = 0;
    if (const char* env = std::getenv("OMP_NUM_THREADS")) threads = std::atoi(env);
    if (threads <= 0) {
        cpu_set_t mask;
        CPU_ZERO(&mask);
        const long online = sysconf(_SC_NPROCESSORS_ONLN);
        threads = sched_getaffinity(0, sizeof mask, &mask) == 0 ? CPU_COUNT(&mask)
                                                                : static_cast<int>(online);
        if (online > 0 && threads >= online && ranks_on_node > 1)
            threads = static_cast<int>(online / ranks_on_node);
    }
    return std::clamp(threads, 1, CW_MAX_BATCH_THREADS);
}

} // namespace cwcampaign
