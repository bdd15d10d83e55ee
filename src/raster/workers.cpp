// The worker threads of a context (workers.h). A job is published by bumping a generation
// counter; each worker runs its share, and the last one to finish wakes the caller. Waiting
// spins briefly (consecutive draws follow each other closely) and then sleeps on the atomic.
#include "raster/workers.h"

#include "raster/bin.h"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <thread>
#include <vector>

namespace pineda {

namespace {

// Spin iterations before sleeping: a few tens of microseconds.
constexpr int kSpinIterations = 2000;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

// Waits until `a` no longer holds `old`; returns the new value. A waiter that stops spinning
// counts itself in `sleepers` while it sleeps, so that changes nobody sleeps on cost no system
// call (notify_change). Both sides use sequentially consistent operations: either the waiter
// sees the new value or the notifier sees the sleeper.
template <class T> T wait_change(const std::atomic<T>& a, T old, std::atomic<int>& sleepers) {
  for (int i = 0; i < kSpinIterations; ++i) {
    const T v = a.load(std::memory_order_acquire);
    if (v != old) return v;
    cpu_relax();
  }
  sleepers.fetch_add(1);
  T v = a.load();
  while (v == old) {
    a.wait(old);
    v = a.load();
  }
  sleepers.fetch_sub(1);
  return v;
}

// Wakes the threads sleeping in wait_change on `a` after it changed, if there are any.
template <class T> void notify_change(std::atomic<T>& a, const std::atomic<int>& sleepers) {
  if (sleepers.load() != 0) a.notify_all();
}

int threads_from_environment() {
  if (const char* s = std::getenv("PINEDA_THREADS"); s != nullptr && *s != '\0') {
    char* end = nullptr;
    const long n = std::strtol(s, &end, 10);
    if (end != s && *end == '\0' && n >= 1)
      return static_cast<int>(std::min<long>(n, kMaxRasterThreads));
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp<unsigned>(hw, 1, kMaxRasterThreads));
}

} // namespace

struct RasterWorkers::Impl {
  explicit Impl(int n) {
    threads.reserve(static_cast<size_t>(n - 1));
    for (int i = 1; i < n; ++i)
      threads.emplace_back([this, i] { worker_main(i); });
  }
  ~Impl() {
    stop = true; // published by the generation bump below
    generation.fetch_add(1);
    generation.notify_all();
    for (std::thread& t : threads)
      t.join();
  }

  void worker_main(int index) {
    uint32_t seen = 0;
    for (;;) {
      seen = wait_change(generation, seen, sleepers);
      if (stop) return;
      fn(arg, index);
      if (pending.fetch_sub(1) == 1) notify_change(pending, sleepers);
    }
  }

  void run(void (*f)(void*, int), void* a) {
    // The previous job has finished (pending reached 0), so no worker reads fn or arg now.
    fn = f;
    arg = a;
    const int others = static_cast<int>(threads.size());
    pending.store(others, std::memory_order_relaxed);
    generation.fetch_add(1);
    notify_change(generation, sleepers);
    f(a, 0);
    for (int p = pending.load(std::memory_order_acquire); p != 0;)
      p = wait_change(pending, p, sleepers);
  }

  std::vector<std::thread> threads;
  void (*fn)(void*, int) = nullptr;
  void* arg = nullptr;
  bool stop = false;
  std::atomic<uint32_t> generation{0};
  std::atomic<int> pending{0};
  // Threads sleeping on generation or pending (wait_change).
  std::atomic<int> sleepers{0};
};

void SpinBarrier::arrive_and_wait() {
  const uint32_t gen = generation_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_) {
    // The last to arrive: nobody touches arrived_ again before the generation moves on.
    arrived_.store(0, std::memory_order_relaxed);
    generation_.fetch_add(1);
    notify_change(generation_, sleepers_);
    return;
  }
  wait_change(generation_, gen, sleepers_);
}

RasterWorkers::RasterWorkers() = default;
RasterWorkers::~RasterWorkers() = default;

int RasterWorkers::threads() {
  if (count_ == 0) count_ = threads_from_environment();
  return count_;
}

bool RasterWorkers::binned() {
  if (binned_ < 0) {
    const char* s = std::getenv("PINEDA_RASTER");
    const std::string_view v = s != nullptr ? s : "";
    binned_ = v == "bins" ? 1 : v == "bands" ? 0 : threads() >= kBinnedFromThreads ? 1 : 0;
  }
  return binned_ != 0;
}

BinStore& RasterWorkers::bin_store() {
  if (!bins_) bins_ = std::make_unique<BinStore>();
  return *bins_;
}

void RasterWorkers::run_impl(void (*fn)(void*, int), void* arg) {
  const int n = threads();
  if (n == 1) {
    fn(arg, 0);
    return;
  }
  if (!impl_) impl_ = std::make_unique<Impl>(n);
  impl_->run(fn, arg);
}

} // namespace pineda
