#include "compare/image_file.h"

#include <OpenImageIO/imagecache.h>
#include <fmt/format.h>

namespace raygate {

OIIO_NAMESPACE::ImageBuf current_image(const std::filesystem::path& path) {
  OIIO_NAMESPACE::ImageCache::create(true)->invalidate(OIIO_NAMESPACE::ustring(path.string()));
  return OIIO_NAMESPACE::ImageBuf(path.string());
}

std::string oversized_image(OIIO_NAMESPACE::ImageBuf& buf, const std::filesystem::path& path) {
  constexpr long long kMaxPixels = 1LL << 27;  // 134 million: 11585 pixels square
  const OIIO_NAMESPACE::ImageSpec& header = buf.spec();
  if (static_cast<long long>(header.width) * header.height <= kMaxPixels) return {};
  return fmt::format("{}: declares {}x{} pixels, more than raygate decodes ({} million)",
                     path.string(), header.width, header.height, kMaxPixels / 1000000);
}

}  // namespace raygate
