#include <mrolr/hw_serial/GreyImage.h>

#include <cstring>
#include <stdexcept>

namespace mrolr::hw_serial
{
namespace
{
/** Copies the rows one by one: the source may be a view with a row stride wider than its width,
 * which MRPT's serialization would reject on the other side. */
mrpt::img::CImage copyRows(const mrpt::img::CImage& grey)
{
	const unsigned w = grey.getWidth(), h = grey.getHeight();
	mrpt::img::CImage out(w, h, mrpt::img::CH_GRAY);
	for (unsigned y = 0; y < h; ++y)
		std::memcpy(out.ptrLine<uint8_t>(y), grey.ptrLine<uint8_t>(y), w);
	return out;
}
}  // namespace

mrpt::img::CImage greyCopy(const mrpt::img::CImage& image, const std::string& what)
{
	if (image.isExternallyStored()) image.forceLoad();
	if (image.isEmpty() || image.getWidth() == 0 || image.getHeight() == 0)
		throw std::invalid_argument(what + " is empty");
	if (image.getPixelDepth() != mrpt::img::PixelDepth::D8U)
		throw std::invalid_argument(what + " does not have 8-bit pixels");
	return copyRows(image.isColor() ? image.grayscale() : image);
}

}  // namespace mrolr::hw_serial
