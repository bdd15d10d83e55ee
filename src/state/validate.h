// Validation (GL state to the state the draws read): validate.cpp runs the areas' derive
// functions and raster_state.cpp derives the back end's RasterState.
#pragma once

#include <cstdint>

#include "state/context.h"

namespace pineda {

// The work of validate_state when something changed.
void validate_changed_state(Context* ctx);

// Brings ctx->raster and the areas' derived state up to date with the GL state. Called for
// every draw: when nothing changed since the last call (no dirty bit, no object of the share
// group changed) it costs two comparisons.
inline void validate_state(Context* ctx) {
  if (ctx->dirty != 0 || ctx->shared->texture_generation != ctx->validated_generation)
    validate_changed_state(ctx);
}

// The back end's RasterState (ctx.raster) from the attribute groups: the parts of `dirty`,
// and the texturing setup the texture area derived (raster_state.cpp).
void derive_raster_state(Context& ctx, uint32_t dirty);

} // namespace pineda
