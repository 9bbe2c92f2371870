#pragma once
/** Errors of the image-level pipeline: bad images, patches or regions given by the caller. */

#include <stdexcept>

namespace mrolr::vision
{
/** Thrown for input the pipeline cannot work on (wrong image type, patch outside the image, a flat
 * patch, …); what() says which input and why. */
class VisionError : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

}  // namespace mrolr::vision
