#include <gtest/gtest.h>
#include <sched.h>

#include "core_affinity.h"

namespace ballbench {

// A timing round runs on the core it names, and the thread runs where it did once the round ends:
// pinned to each core this process may use in turn, the thread is found on that core, and the
// cores allowed afterwards are the ones before.
TEST(CoreAffinity, APinRunsTheThreadOnItsCoreAndRestoresItsCores) {
  const std::vector<int> cores = allowed_cores();
  ASSERT_FALSE(cores.empty());
  for (int c : cores) {
    {
      const CorePin pin(c);
      EXPECT_EQ(allowed_cores(), std::vector<int>{c});
      EXPECT_EQ(::sched_getcpu(), c);
    }
    EXPECT_EQ(allowed_cores(), cores);
  }
  {
    const CorePin none(-1);  // no pin: where it was
    EXPECT_EQ(allowed_cores(), cores);
  }
  {
    const CorePin refused(1 << 20);  // past any machine's cores: refused, nothing changed
    EXPECT_EQ(allowed_cores(), cores);
  }
  EXPECT_EQ(allowed_cores(), cores);
}

}  // namespace ballbench
