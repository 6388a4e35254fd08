// Aperture stop masks for the realistic camera (pbrt-v4's "aperture" parameter).
#pragma once

#include <optional>
#include <string>

#include "core/image/image.h"

namespace kiln {

// pbrt-v4's built-in diaphragm shapes, 256x256 single-channel images over [-1,1]^2 (rows
// along +y): "gaussian" max(0, exp(-r^2) - exp(-1)), "square" 1 on [-1/2, 1/2]^2,
// "pentagon" a regular pentagon of circumradius 0.8 with a vertex on +y, "star" a five-pointed
// star of outer radius 1 and inner radius cos 72 deg / cos 36 deg with points at 36 deg +
// k 72 deg; each pixel is evaluated at its centre. nullopt for other names.
std::optional<Image> BuiltinApertureMask(const std::string& name);

// A mask from an image file's pixels: its one channel, or the mean of R, G and B; nullopt with
// a message in *error if it has several channels but not R, G and B.
std::optional<Image> ApertureMaskFromImage(const Image& image, std::string* error);

// As pbrt-v4 prepares every mask: rows flipped (the first row becomes the last), then scaled
// so that its mean is pi / 4, the fraction of the square a circular stop covers, so that the
// mask passes as much light as the circular stop it replaces. False (mask unchanged) if its
// mean is not positive and finite.
bool NormalizeApertureMask(Image* mask);

}  // namespace kiln
