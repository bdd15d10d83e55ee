// Worker threads of one context for rasterization and clears (issue 6).
//
// A draw with enough work is run by T threads at once (the calling thread is one of them).
// Each runs primitive assembly, clipping, culling and setup for every primitive of the draw in
// API order but rasterizes only the pixels of its own bands: window rows y with
// (y >> kBandShift) mod T equal to its index. Every pixel is thus written by exactly one
// thread, in the order the primitives were given, so the image is the same bit for bit as the
// single-threaded one (GL 2.1 §2.1 and Appendix A ask for in-order, repeatable results).
//
// Filled triangles may instead be binned (raster/bin.h; binned() chooses): set up once, by
// one thread each, into records binned by screen tile, and drawn a tile per thread at a time.
//
// The threads are created on the first draw that uses them, not with the context (programs
// create and destroy many contexts), and joined when the context is destroyed. PINEDA_THREADS
// sets their number (1 keeps everything on the calling thread); by default it is the number
// of hardware threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>

namespace pineda {

struct BinStore; // raster/bin.h

// Bands are 32 rows high: a multiple of the 8-row blocks of the fragment stage (a block never
// straddles two bands), small enough to spread a primitive over the workers, large enough that
// few small primitives straddle two (which costs both workers the setup).
constexpr int kBandShift = 5;
constexpr int kMaxRasterThreads = 64;
// Binning pays for its records and its barrier per batch by setting each triangle up once,
// where bands make every thread assemble every primitive (README, Performance: Worker
// threads): on two cores bands measured faster, while their per-thread work has a floor that
// more threads do not divide.
constexpr int kBinnedFromThreads = 3;

// One worker's share of the window: count workers, this one is index.
struct Bands {
  int count = 1; // 1: every row
  int index = 0;

  // Whether window row y (inside the framebuffer, so y >= 0) is this worker's.
  bool owns(int y) const {
    return count == 1 || static_cast<int>(static_cast<unsigned>(y >> kBandShift) %
                                          static_cast<unsigned>(count)) == index;
  }
  // Whether any row of [y0, y1] is this worker's; rows below 0 hold no pixels.
  bool owns_any(int y0, int y1) const {
    if (count == 1) return true;
    y0 = std::max(y0, 0);
    if (y1 < y0) return false;
    const int b0 = y0 >> kBandShift, b1 = y1 >> kBandShift;
    if (b1 - b0 + 1 >= count) return true;
    for (int b = b0; b <= b1; ++b)
      if (b % count == index) return true;
    return false;
  }
};

// A barrier for the threads of one RasterWorkers::run job (binned draws, bin.h): each call of
// arrive_and_wait returns once all `count` threads have made their matching call. Waiting spins
// briefly, then sleeps.
class SpinBarrier {
public:
  explicit SpinBarrier(int count) : count_(count) {}
  void arrive_and_wait();

private:
  const int count_;
  std::atomic<int> arrived_{0};
  std::atomic<uint32_t> generation_{0};
  std::atomic<int> sleepers_{0};
};

// The worker threads of one context. Used by one thread at a time (the one the context is
// current on).
class RasterWorkers {
public:
  RasterWorkers();
  ~RasterWorkers();
  RasterWorkers(const RasterWorkers&) = delete;
  RasterWorkers& operator=(const RasterWorkers&) = delete;

  // Threads a shared draw uses, the calling thread included, 1..kMaxRasterThreads:
  // PINEDA_THREADS when set, else the hardware's thread count. Read on the first call.
  int threads();

  // Whether shared draws of filled triangles are binned (raster/bin.h) rather than shared by
  // bands: PINEDA_RASTER=bins or bands when set; otherwise bins from kBinnedFromThreads
  // threads up. Read on the first call.
  bool binned();

  // Runs f(i) for i in [0, threads()), f(0) on the calling thread and the others on the worker
  // threads (started on first use), and returns when all have returned.
  template <class F> void run(F& f) {
    run_impl([](void* p, int i) { (*static_cast<F*>(p))(i); }, &f);
  }

  // The bins of binned draws (raster/bin.h), made on first use and kept for their capacity.
  BinStore& bin_store();

private:
  struct Impl;
  void run_impl(void (*fn)(void*, int), void* arg);
  int count_ = 0;   // 0: not read yet
  int binned_ = -1; // -1: not read yet
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<BinStore> bins_;
};

} // namespace pineda
