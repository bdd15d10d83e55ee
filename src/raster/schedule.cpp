// The sharing of back-end work among the worker threads (schedule.h).
#include "raster/schedule.h"

#include <algorithm>
#include <atomic>
#include <cstdint>

#include "raster/bin.h"

namespace pineda {

namespace {

// Clears of at least this many pixels are shared among the worker threads, in runs of at
// least kShareClearRows rows.
constexpr int64_t kShareClearArea = 512 * 1024;
constexpr int kShareClearRows = 16;

} // namespace

void draw_banded(const DrawCall& dc, const FragCtx& frag, RasterWorkers& workers, int n,
                 const AssemblyJob& job) {
  uint64_t samples[kMaxRasterThreads] = {};
  auto part = [&](int i) {
    FragCtx local = frag;
    DrawCall share = dc;
    share.frag = &local;
    share.samples_passed = &samples[i];
    share.bands = Bands{n, i};
    job.all(share, job.mode, job.verts, job.indices, job.count);
  };
  workers.run(part);
  if (dc.samples_passed != nullptr)
    for (int i = 0; i < n; ++i)
      *dc.samples_passed += samples[i];
}

// Triangles each thread sets up per batch (bin.h). Measured on bench_lit_mesh at two threads:
// 1024 per batch 16.5 ms, 4096 15.5 ms, 16384 14.1 ms: fewer barriers matter more than records
// that stay in the cache.
constexpr size_t kBatchTriangles = 16384;
// Draws of at most this many units are set up by the calling thread alone before the workers
// are woken: a full-screen quad would otherwise wait for a worker to wake up and set it up.
constexpr size_t kCallerSetupUnits = 32;

// Runs a draw of filled triangles on `n` threads in batches of two phases (bin.h): setup into
// each thread's bins, then the tiles. Each thread has two sets of bins and sets up batch k + 1
// into one while the tiles of batch k are drawn from the other, so one barrier per batch
// separates the phases: when a thread passes barrier k, every thread has finished drawing
// batch k - 1 (whose set batch k + 1 reuses) and setting up batch k.
void draw_binned(const DrawCall& dc, const FragCtx& frag, RasterWorkers& workers, int n,
                 const AssemblyJob& job) {
  const size_t units = job.units;
  const size_t per_thread =
      job.mode == GL_QUADS || job.mode == GL_QUAD_STRIP ? kBatchTriangles / 2 : kBatchTriangles;
  const size_t batch = per_thread * static_cast<size_t>(n);
  const size_t batches = (units + batch - 1) / batch;
  const bool caller_setup = units <= kCallerSetupUnits;
  const TileGrid grid = make_tile_grid(frag);
  BinStore& store = workers.bin_store();
  uint64_t samples[kMaxRasterThreads] = {};
  // The next tile of batch k to hand out, in next_tile[k & 1]: reset for batch k + 2 by
  // thread 0 once barrier k + 1 shows every thread done with batch k.
  std::atomic<int> next_tile[2] = {0, 0};
  SpinBarrier barrier(n);
  const auto nt = static_cast<size_t>(n);
  // Phase 1 of batch k for thread i: its contiguous share of the batch's primitives.
  const auto set_up = [&](int i, size_t k, size_t share_of, size_t shares) {
    TriBins& b = store.sets[k & 1][i];
    b.reset(grid);
    DrawCall setup_dc = dc;
    setup_dc.bands = Bands{};
    setup_dc.stipple_counter = nullptr; // filled polygons have no stipple counter
    const size_t first = k * batch, m = std::min(batch, units - first);
    const size_t lo = first + m * share_of / shares, hi = first + m * (share_of + 1) / shares;
    job.range(b, setup_dc, job.mode, job.verts, job.indices, job.count, lo, hi);
    b.link_shades();
  };
  if (caller_setup) {
    set_up(0, 0, 0, 1);
    for (int i = 1; i < n; ++i)
      store.sets[0][i].reset(grid);
  }
  auto part = [&](int i) {
    FragCtx local = frag;
    DrawCall share = dc;
    share.frag = &local;
    share.bands = Bands{};
    // Phase 2 of batch k: the tiles inside the union of the threads' binned ranges, handed
    // out a run at a time, so a thread that started late (a worker waking up) takes fewer.
    const auto draw_tiles = [&](size_t k) {
      const TriBins* set[kMaxRasterThreads];
      int tx0 = grid.tiles_x, ty0 = grid.tiles_y, tx1 = -1, ty1 = -1;
      for (int t = 0; t < n; ++t) {
        set[t] = &store.sets[k & 1][t];
        tx0 = std::min(tx0, set[t]->tx0), tx1 = std::max(tx1, set[t]->tx1);
        ty0 = std::min(ty0, set[t]->ty0), ty1 = std::max(ty1, set[t]->ty1);
      }
      if (tx1 < tx0 || ty1 < ty0) return;
      const int w = tx1 - tx0 + 1, total = w * (ty1 - ty0 + 1);
      const int run = std::max(1, total / (8 * n));
      std::atomic<int>& next = next_tile[k & 1];
      for (int j = next.fetch_add(run, std::memory_order_relaxed); j < total;
           j = next.fetch_add(run, std::memory_order_relaxed))
        for (int e = std::min(j + run, total); j < e; ++j) {
          const auto tile = static_cast<size_t>((ty0 + j / w) * grid.tiles_x + tx0 + j % w);
          bool empty = true;
          for (int t = 0; t < n; ++t)
            empty &= set[t]->head[tile] == kNoIndex;
          if (!empty) raster_tile(share, local, set, n, static_cast<int>(tile));
        }
    };
    if (!caller_setup) {
      set_up(i, 0, static_cast<size_t>(i), nt);
      barrier.arrive_and_wait();
    }
    for (size_t k = 0; k < batches; ++k) {
      draw_tiles(k);
      if (k + 1 < batches) {
        if (i == 0 && k >= 1) next_tile[(k + 1) & 1].store(0, std::memory_order_relaxed);
        set_up(i, k + 1, static_cast<size_t>(i), nt);
        barrier.arrive_and_wait();
      }
    }
    samples[i] = local.samples_passed;
  };
  workers.run(part);
  if (dc.samples_passed != nullptr)
    for (int i = 0; i < n; ++i)
      *dc.samples_passed += samples[i];
}

void clear_buffers_shared(RasterWorkers* workers, Framebuffer& fb, const ClearState& cs,
                          GLbitfield mask) {
  const ClearRect r = clear_rect(fb, cs);
  const int64_t area = int64_t{std::max(r.w(), 0)} * std::max(r.h(), 0);
  if (workers != nullptr && area >= kShareClearArea && r.h() >= 2 * kShareClearRows) {
    const int n = std::min(workers->threads(), r.h() / kShareClearRows);
    if (n > 1) {
      auto job = [&](int i) {
        if (i >= n) return;
        ClearRect part = r;
        part.y0 = r.y0 + static_cast<int>(int64_t{r.h()} * i / n);
        part.y1 = r.y0 + static_cast<int>(int64_t{r.h()} * (i + 1) / n);
        clear_buffers(fb, cs, mask, part);
      };
      workers->run(job);
      return;
    }
  }
  clear_buffers(fb, cs, mask, r);
}

} // namespace pineda
