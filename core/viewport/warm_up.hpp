// Machine code for a structure's programs before the frame that first needs them.
//
// llvmpipe (Mesa's software driver, the one CI and GPU-less users run on) translates a compute
// program to machine code at its first dispatch, not when it is linked: a new structure's first
// full frame spent 100-350 ms of the editor's main thread in LLVM. The translation is keyed by the
// program and the formats of what is bound, and it lands in Mesa's shader cache, which every
// context of the process reads. So a worker that has just linked the programs on its shared
// context renders a few tiny frames through every pass with them, and the main thread's first
// dispatch finds the machine code there. On a driver that translates at link time this costs a
// few dispatches of a 24x24 grid.
#pragma once

#include <memory>

#include "core/formula.hpp"
#include "core/viewport/viewport_programs.hpp"

namespace fraktal::viewport {

// Which frames a viewport of these programs will render: a view that only refines at rest (a
// thumbnail) never runs the reprojection, the march list, the motion filter or the cone pre-pass.
enum class WarmUpFrames { StillAndMotion, Still };

// Renders tiny frames with `programs` (built for `formula`'s structure) on the calling thread's
// context: a reset, a frame at rest and sliced frames at rest; with motion also the cone pre-pass
// and two reprojected frames on a smaller grid (the resampling blit too). Returns the programs,
// unchanged. Best effort: a failure leaves the translation to the first real frame.
std::unique_ptr<ViewportPrograms> warmUp(std::unique_ptr<ViewportPrograms> programs, const Formula& formula,
                                         WarmUpFrames frames = WarmUpFrames::StillAndMotion);

}  // namespace fraktal::viewport
