// Binned rasterization of filled triangles shared by the worker threads (issue 6).
//
// A shared draw of filled triangles runs in batches of two phases, every worker thread taking
// part in both (raster/schedule.cpp, draw_binned):
//  1. Setup. Each thread takes its own contiguous run of the batch's primitives, in API order,
//     and runs assembly, clipping, culling and triangle setup (edge functions, bounding box,
//     the coverage of one-block triangles and the interpolation planes) once per triangle. The
//     result is a TriBins record, linked into the bin of every 64x64 screen tile the triangle
//     may touch.
//  2. Rasterization. The threads take tiles one at a time from a shared counter. A tile's
//     triangles are those of thread 0's bin, then thread 1's, ...: API order, since the runs are
//     contiguous and in thread order. Each triangle is traversed within the tile only.
// Every pixel belongs to one tile, and a tile is drawn by one thread in API order, so the image
// is the same bit for bit for any thread count (GL 2.1 §2.1, Appendix A) and whichever thread
// draws which tile.
//
// Each thread has two sets of bins: batch k + 1 is set up into one while the tiles of batch k are
// drawn from the other, so one barrier per batch separates the phases. Batches are large (16384
// triangles per thread): each barrier costs the threads' imbalance in its batch, which
// measured more than the records falling out of the cache. The calling thread sets up a draw of
// a few large primitives alone before waking the workers, which then only draw tiles.
//
// RasterWorkers::binned chooses between this and the bands of workers.h.
#pragma once

#include <cstdint>
#include <vector>

#include "fragment/fragment_ops.h"
#include "fragment/shade.h"
#include "raster/raster.h"
#include "raster/setup.h"

namespace pineda {

// Tiles are 64x64 pixels, aligned to multiples of 64 in window space: eight by eight of the
// fragment stage's blocks, so no block straddles two tiles.
constexpr int kTileShiftX = 6;
constexpr int kTileShiftY = 6;
constexpr int kTileW = 1 << kTileShiftX, kTileH = 1 << kTileShiftY;

// The tiles of a draw: those covering [0, clip_x1] x [0, clip_y1] of the clip rectangle.
struct TileGrid {
  int tiles_x = 0, tiles_y = 0;
  int count() const { return tiles_x * tiles_y; }
};

inline TileGrid make_tile_grid(const FragCtx& ctx) {
  TileGrid g;
  if (ctx.clip_x1 >= ctx.clip_x0 && ctx.clip_y1 >= ctx.clip_y0) {
    g.tiles_x = (ctx.clip_x1 >> kTileShiftX) + 1;
    g.tiles_y = (ctx.clip_y1 >> kTileShiftY) + 1;
  }
  return g;
}

constexpr uint32_t kNoIndex = ~uint32_t{0};

// One set-up triangle.
struct BinnedTri {
  FragInputs in; // in.shade is set once the thread's setup phase is over (shade index)
  BlockFn fn = nullptr;
  uint64_t mask = 0;       // one-block triangles: the coverage of block (bx, by)
  int32_t bx = -1, by = 0; // bx < 0: traversed with edges[edge_index]
  uint32_t edge_index = kNoIndex;
  uint32_t shade_index = kNoIndex;
};

// One thread's records and bins, kept across draws (their capacity is reused). Aligned to two
// cache lines so that no two threads' vector ends and ranges, written per triangle, share one.
struct alignas(128) TriBins {
  struct Entry {
    uint32_t tri;
    uint32_t next; // the tile's next entry, or kNoIndex
  };
  std::vector<BinnedTri> tris;
  std::vector<TriEdges> edges;
  std::vector<ShadeInputs> shades;
  std::vector<Entry> entries;
  std::vector<uint32_t> head, tail; // per tile: first and last entry, or kNoIndex
  TileGrid grid;
  // The tiles binned into since reset(), as an inclusive range (empty when tx0 > tx1): the
  // rasterization phase looks only at the union of the threads' ranges.
  int tx0 = 1 << 30, ty0 = 1 << 30, tx1 = -1, ty1 = -1;

  // Empties the bins for a batch of `grid`.
  void reset(const TileGrid& g);
  // Links record `tri` into tile (tx, ty).
  void add(uint32_t tri, int tx, int ty) {
    const auto tile = static_cast<size_t>(ty * grid.tiles_x + tx);
    const auto e = static_cast<uint32_t>(entries.size());
    entries.push_back({tri, kNoIndex});
    if (head[tile] == kNoIndex)
      head[tile] = e;
    else
      entries[tail[tile]].next = e;
    tail[tile] = e;
    tx0 = tx < tx0 ? tx : tx0;
    tx1 = tx > tx1 ? tx : tx1;
    ty0 = ty < ty0 ? ty : ty0;
    ty1 = ty > ty1 ? ty : ty1;
  }
  // Points the records' in.shade at their ShadeInputs (the vector has stopped growing).
  void link_shades();
};

// The bins of a context's worker threads (RasterWorkers::bin_store): two sets per thread, one
// being drawn while the next batch is set up into the other.
struct BinStore {
  TriBins sets[2][kMaxRasterThreads];
};

// Phase 1 for one triangle that survived clipping and culling, its positions snapped: setup,
// and a record in the bins of the tiles it may touch. The arguments are raster_triangle's.
void bin_triangle(TriBins& bins, const DrawCall& dc, const SnappedTri& t, const PVertex& a,
                  const PVertex& b, const PVertex& c, const PVertex& provoking, bool back_facing);

// Phase 2 for one tile: the records of bins[0..n) for tile `tile`, in that order, drawn within
// the tile with the thread's own fragment context `ctx`.
void raster_tile(const DrawCall& dc, const FragCtx& ctx, const TriBins* const* bins, int n,
                 int tile);

} // namespace pineda
