#include "nonhertz/patches.hpp"

#include <cstddef>

namespace creepwork {

PatchLabels::PatchLabels(int nx, int ny)
    : nx_(nx), ny_(ny), label_(static_cast<std::size_t>(nx) * ny, -1),
      queue_(static_cast<std::size_t>(nx) * ny, 0)
{
}

int PatchLabels::label(const signed char* in_contact)
{
    const int n = nx_ * ny_;
    for (int k = 0; k < n; ++k) label_[k] = -1;
    count_ = 0;
    for (int seed = 0; seed < n; ++seed) {
        if (!in_contact[seed] || label_[seed] >= 0) continue;
        // Breadth-first over edge neighbours; each element enters the queue once.
        int head = 0, tail = 0;
        queue_[tail++] = seed;
        label_[seed] = count_;
        while (head < tail) {
            const int k = queue_[head++];
            const int i = k % nx_, j = k / nx_;
            const int next[4] = {i > 0 ? k - 1 : -1, i + 1 < nx_ ? k + 1 : -1,
                                 j > 0 ? k - nx_ : -1, j + 1 < ny_ ? k + nx_ : -1};
            for (int m : next)
                if (m >= 0 && in_contact[m] && label_[m] < 0) {
                    label_[m] = count_;
                    queue_[tail++] = m;
                }
        }
        ++count_;
    }
    return count_;
}

} // namespace creepwork
