#pragma once
/** Textures of the simulated lab, made by code (no downloads) or read from image files.
 *
 * A texture spec is either `procedural:<pattern>[:<seed>]` with pattern one of wall, floor,
 * ceiling, light (a ceiling light fitting, thesis fig 5.6.2.1), fire_sign (the known feature of
 * 5.6.2), poster (random high-contrast shapes), speckle (dense random grey blobs, for obstacles
 * that stereo must see), checker; or an image path, relative to the world
 * file's folder unless absolute. */

#include <mrpt/img/CImage.h>

#include <string>
#include <vector>

namespace mrolr::sim
{
/** The procedural patterns makeProceduralTexture knows. */
const std::vector<std::string>& proceduralPatterns();

/** A colour texture of @p pattern (see above), 256×256 pixels, deterministic for @p seed. Throws
 * std::invalid_argument naming the pattern if it is unknown. */
mrpt::img::CImage makeProceduralTexture(const std::string& pattern, unsigned seed);

/** The texture for @p spec; relative image paths are resolved against @p base_dir. Throws
 * std::runtime_error naming the spec and path when the file cannot be read. */
mrpt::img::CImage loadTexture(const std::string& spec, const std::string& base_dir);

}  // namespace mrolr::sim
