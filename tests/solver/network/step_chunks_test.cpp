// Work over steps takes one chunk per core the process may run on (its CPU affinity, as
// Slurm's --cpus-per-task or taskset set it), not every core of the machine.

#include "solver/network/step_chunks.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

namespace gesmi {
namespace {

TEST(StepChunks, OneChunkPerUsableCoreAndNoneTooSmall) {
  // In a child, so that this process's own affinity (and usable_cores' cache) stays.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    cpu_set_t all, one;
    CPU_ZERO(&one);
    if (::sched_getaffinity(0, sizeof(all), &all) != 0) ::_exit(2);
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
      if (CPU_ISSET(cpu, &all)) {
        CPU_SET(cpu, &one);
        break;
      }
    if (::sched_setaffinity(0, sizeof(one), &one) != 0) ::_exit(3);
    ::_exit(usable_cores() == 1 && step_chunk_count(10000000) == 1 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "with one core allowed, the work still took several chunks";
  EXPECT_GE(usable_cores(), 1u);
  EXPECT_LE(usable_cores(), std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(step_chunk_count(10), 1u);  // fewer steps than a chunk's worth
  EXPECT_EQ(step_chunk_count(kMinStepsPerChunk * 100), usable_cores());
}

}  // namespace
}  // namespace gesmi
