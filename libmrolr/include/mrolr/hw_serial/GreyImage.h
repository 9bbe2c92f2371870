#pragma once
/** The one image form the camera paths hand on: 8-bit greyscale, held in memory. */

#include <mrpt/img/CImage.h>

#include <string>

namespace mrolr::hw_serial
{
/** A deep, in-memory, 8-bit greyscale copy of @p image, its pixels untouched when it is already
 * 8-bit grey (colour goes through CImage::grayscale()). An externally stored image is loaded
 * first, so the copy never refers to a file. Throws std::invalid_argument naming @p what ("left
 * image") when the image is empty or its pixels are not 8-bit. */
mrpt::img::CImage greyCopy(const mrpt::img::CImage& image, const std::string& what);

}  // namespace mrolr::hw_serial
