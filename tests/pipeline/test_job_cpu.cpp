// A job's CPU time over every thread that works for it (pipeline/job_cpu.hpp).
#include "pipeline/job_cpu.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>

namespace {

// Busy work whose result the compiler cannot drop.
double spin(int n) {
  double x = 1;
  for (int i = 0; i < n; ++i) x = std::sqrt(x + i);
  return x;
}

}  // namespace

// The calling thread's time plus the workers' time in the arena covers the work of every task,
// whichever threads ran them, and counts nothing twice (at most the process's CPU time).
TEST(JobCpu, ArenaWorkersAndTheCallingThreadCoverEveryTask) {
  tbb::task_arena arena(2, 1, tbb::task_arena::priority::high);
  std::atomic<double> tasks{0};
  std::atomic<double> sink{0};
  const double process0 = mc::pipeline::process_cpu_seconds();
  const double self0 = mc::pipeline::thread_cpu_seconds();
  double workers = 0;
  {
    mc::pipeline::ArenaWorkerCpu observer(arena);
    arena.execute([&] {
      tbb::parallel_for(0, 400, [&](int) {
        const double t0 = mc::pipeline::thread_cpu_seconds();
        sink.fetch_add(spin(200000));
        tasks.fetch_add(mc::pipeline::thread_cpu_seconds() - t0);
      });
    });
    workers = observer.close();
  }
  const double self = mc::pipeline::thread_cpu_seconds() - self0;
  const double process = mc::pipeline::process_cpu_seconds() - process0;
  EXPECT_GT(sink.load(), 0);
  ASSERT_GT(tasks.load(), 0.05);  // enough work to measure
  EXPECT_GE(workers, 0);
  EXPECT_GE(self + workers, 0.95 * tasks.load()) << "self " << self << " workers " << workers;
  EXPECT_LE(self + workers, process + 0.02) << "self " << self << " workers " << workers;
}

// Without an arena the calling thread's clock is its own: it does not move while it sleeps.
TEST(JobCpu, ThreadClockCountsOnlyThisThreadsWork) {
  const double t0 = mc::pipeline::thread_cpu_seconds();
  volatile double x = spin(2000000);
  (void)x;
  const double t1 = mc::pipeline::thread_cpu_seconds();
  EXPECT_GT(t1, t0);
  timespec pause{0, 50'000'000};
  nanosleep(&pause, nullptr);
  EXPECT_LT(mc::pipeline::thread_cpu_seconds() - t1, 0.02);
}
