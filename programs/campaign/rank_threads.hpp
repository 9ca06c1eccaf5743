// How many OpenMP threads a rank's batches use when --threads is not given.
#pragma once

namespace cwcampaign {

// OMP_NUM_THREADS when set (its first entry); otherwise the CPUs in this
// process's affinity mask -- what the launcher bound the rank to -- except
// that ranks left unbound (their mask is the whole node) share the node's
// CPUs: online / ranks_on_node. At least 1, at most CW_MAX_BATCH_THREADS.
int default_threads(int ranks_on_node);

} // namespace cwcampaign
