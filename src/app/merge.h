// `kiln merge`: renders made in pieces put back together (issue 14's farm runs tiles and seeds
// as separate processes).
//
//   kiln merge PART.exr... -o FULL.exr            tiles (--pixelbounds renders) of one frame
//   kiln merge --samples RENDER.exr... -o OUT.exr  renders of the same pixels with different
//                                                   seeds, weighted by their samples per pixel
//   --memory-limit SIZE                             the parts (charged from their headers) and the
//                                                   merged frame must fit in SIZE
//
// Tiles are assembled by their EXR data windows into the display window. kiln writes a tile in
// 32-bit float (film.cpp) with the film's savefp16 choice in its metadata; the merged frame is
// then written as the whole-frame render would have been (half float if every part asked for
// it and no value passes 65504), so it is bit-identical to a single-process render of the same
// scene, seed and spp. Refused, with nothing written: parts from different scenes (kiln:scene,
// a hash of every file the scene read: render/scene_inputs.h), render options that change pixels
// (kiln:options, render/render_options.h: RenderOptionsKey), frames, seeds, sample counts,
// exposures, resolutions or channels; parts with a non-finite pixel; partial (interrupted) tiles;
// overlapping tiles (both named); missing pixels (how many, and the box around them).
//
// --samples: the parts cover the same pixels with different seeds (the same seed twice is the
// same samples and is refused); the result is sum(spp_i v_i) / sum(spp_i) with spp = sum(spp_i):
// the estimate a render with the summed samples makes (not bit-identical to one: its samples
// are different ones). Interrupted renders count with the samples they hold.
#pragma once

#include <string>
#include <vector>

#include "core/image/image.h"

namespace kiln {

// A rendered image and its metadata as read from an EXR.
struct RenderPart {
    std::string file;
    Image image;
    ImageMetadata metadata;
};

// Assemble tiles / combine sample sets; throw std::runtime_error saying what is wrong.
Image MergeTiles(const std::vector<RenderPart>& parts, ImageMetadata* metadata);
Image MergeSamples(const std::vector<RenderPart>& parts, ImageMetadata* metadata);

// Writes a merged image as kiln writes a render: EXR, half float when every part's
// kiln:savefp16 is true and no value passes 65504.
void WriteMerged(const Image& image, const ImageMetadata& metadata, const std::string& filename);

// `kiln merge ...` (args without "merge"): 0 on success, 1 when the parts cannot be merged
// (message on stderr, nothing written), 2 on usage errors.
int RunMerge(const std::vector<std::string>& args);

}  // namespace kiln
