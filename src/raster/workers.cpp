// The worker threads of a context (workers.h). A job is published by bumping a generation
// counter; each worker runs its share, and the last one to finish wakes the caller. Waiting
// spins briefly (consecutive draws follow each other closely) and then sleeps on the atomic.
#include "raster/workers.h"

#include <atomic>
#include <cstdint>
#include <cstdlib>
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

// Waits until `a` no longer holds `old`; returns the new value.
template <class T> T wait_change(const std::atomic<T>& a, T old) {
  for (int i = 0; i < kSpinIterations; ++i) {
    const T v = a.load(std::memory_order_acquire);
    if (v != old) return v;
    cpu_relax();
  }
  for (;;) {
    a.wait(old, std::memory_order_acquire);
    const T v = a.load(std::memory_order_acquire);
    if (v != old) return v;
  }
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
    generation.fetch_add(1, std::memory_order_release);
    generation.notify_all();
    for (std::thread& t : threads)
      t.join();
  }

  void worker_main(int index) {
    uint32_t seen = 0;
    for (;;) {
      seen = wait_change(generation, seen);
      if (stop) return;
      fn(arg, index);
      if (pending.fetch_sub(1, std::memory_order_acq_rel) == 1) pending.notify_one();
    }
  }

  void run(void (*f)(void*, int), void* a) {
    // The previous job has finished (pending reached 0), so no worker reads fn or arg now.
    fn = f;
    arg = a;
    const int others = static_cast<int>(threads.size());
    pending.store(others, std::memory_order_relaxed);
    generation.fetch_add(1, std::memory_order_release);
    generation.notify_all();
    f(a, 0);
    for (int p = pending.load(std::memory_order_acquire); p != 0;)
      p = wait_change(pending, p);
  }

  std::vector<std::thread> threads;
  void (*fn)(void*, int) = nullptr;
  void* arg = nullptr;
  bool stop = false;
  std::atomic<uint32_t> generation{0};
  std::atomic<int> pending{0};
};

RasterWorkers::RasterWorkers() = default;
RasterWorkers::~RasterWorkers() = default;

int RasterWorkers::threads() {
  if (count_ == 0) count_ = threads_from_environment();
  return count_;
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
